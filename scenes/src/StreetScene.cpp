#include "penumbra/scenes/TestScenes.hpp"

#include "penumbra/scene/MeshGenerators.hpp"

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <optional>
#include <string>

namespace penumbra::scenes {
namespace {

// Every size of the street, in metres.
constexpr float kHalfLength = 192.0f; // the street runs along z from -192 to 192
constexpr float kRoadHalfWidth = 6.0f;
constexpr float kFacadeX = 12.0f; // the buildings' fronts; the pavements run from the road to them
constexpr float kPavementTop = 0.15f;
constexpr std::uint32_t kBuildingsPerSide = 20;
constexpr float kBuildingDepth = 12.0f;
constexpr std::uint32_t kLampsPerRow = kStreetLamps / 4; // two rows of posts at the kerbs, two on the facades
constexpr float kLampPitch = 2.0f * kHalfLength / kLampsPerRow;
constexpr float kPostX = 7.0f;
constexpr float kPostHeight = 5.0f;
constexpr float kFacadeLampX = 11.6f;
constexpr float kFacadeLampHeight = 3.5f;
constexpr std::uint32_t kWindowsPerSide = kStreetShopWindows / 2;
constexpr std::uint32_t kTreesPerSide = 24;
constexpr float kTreeX = 9.5f;
constexpr float kParkedCarX = 4.8f;

constexpr std::array kWindowColours{glm::vec3{1.0f, 0.85f, 0.6f}, glm::vec3{0.7f, 0.85f, 1.0f},
                                    glm::vec3{1.0f, 0.6f, 0.7f}, glm::vec3{0.8f, 1.0f, 0.7f}};

glm::mat4 placed(glm::vec3 centre, glm::vec3 scale)
{
    return glm::scale(glm::translate(glm::mat4(1.0f), centre), scale);
}

// 1 for the +x side of the street, -1 for the -x side.
float side(std::uint32_t i) { return i % 2 == 0 ? -1.0f : 1.0f; }

// Position along the street of the k-th item of a row of `count` spread over the street, from the camera's end (+z).
float along(std::uint32_t k, std::uint32_t count, float offset = 0.0f)
{
    const float pitch = 2.0f * kHalfLength / static_cast<float>(count);
    return kHalfLength - pitch * (static_cast<float>(k) + 0.5f) + offset;
}

struct Shapes {
    std::uint32_t box; // unit cube centred on the origin
    std::uint32_t trunk;
    std::uint32_t crown;
    std::uint32_t post;
};

void addBuildings(scene::Scene& scene, const Shapes& shapes, std::uint32_t walls)
{
    const float length = 2.0f * kHalfLength / kBuildingsPerSide;
    for (std::uint32_t i = 0; i < 2 * kBuildingsPerSide; ++i) {
        const std::uint32_t k = i / 2;
        const float height = 8.0f + 4.0f * static_cast<float>((k * 7 + i) % 5);
        const glm::vec3 centre{side(i) * (kFacadeX + 0.5f * kBuildingDepth), 0.5f * height,
                               along(k, kBuildingsPerSide)};
        scene.addObject("building " + std::to_string(i + 1), shapes.box, walls,
                        placed(centre, {kBuildingDepth, height, length - 1.0f}));
    }
}

void addTreesAndPosts(scene::Scene& scene, const Shapes& shapes, std::uint32_t bark, std::uint32_t leaves,
                      std::uint32_t metal)
{
    for (std::uint32_t i = 0; i < 2 * kTreesPerSide; ++i) {
        // Between lamp posts: a tree every 16 m, offset by half a lamp pitch.
        const glm::vec3 base{side(i) * kTreeX, kPavementTop, along(i / 2, kTreesPerSide, 0.5f * kLampPitch)};
        const std::string name = "tree " + std::to_string(i + 1);
        scene.addObject(name + "/0", shapes.trunk, bark, glm::translate(glm::mat4(1.0f), base + glm::vec3(0, 1.5f, 0)));
        scene.addObject(name + "/1", shapes.crown, leaves,
                        glm::translate(glm::mat4(1.0f), base + glm::vec3(0, 4.0f, 0)));
    }
    for (std::uint32_t i = 0; i < 2 * kLampsPerRow; ++i)
        scene.addObject("post " + std::to_string(i + 1), shapes.post, metal,
                        glm::translate(glm::mat4(1.0f), {side(i) * kPostX, kPavementTop + 0.5f * kPostHeight,
                                                         along(i / 2, kLampsPerRow)}));
}

// Where car i (0-based) is parked: in gaps of varying length along both kerbs.
glm::vec3 parkedCar(std::uint32_t i)
{
    return {side(i) * kParkedCarX, 0.65f, along(i / 2, kStreetCars / 2, 3.0f * static_cast<float>(i % 3) - 3.0f)};
}

std::string carName(std::uint32_t i) { return "car " + std::to_string(i + 1); }

// A car's body and its cabin, around the body's centre.
std::array<glm::mat4, 2> carParts(glm::vec3 body)
{
    return {placed(body, {1.8f, 0.9f, 4.3f}), placed(body + glm::vec3(0, 0.75f, -0.2f), {1.6f, 0.6f, 2.2f})};
}

void addCars(scene::Scene& scene, const Shapes& shapes, std::uint32_t paint, std::uint32_t glass)
{
    for (std::uint32_t i = 0; i < kStreetCars; ++i) {
        const std::array<glm::mat4, 2> parts = carParts(parkedCar(i));
        scene.addObject(carName(i) + "/0", shapes.box, paint, parts[0]);
        scene.addObject(carName(i) + "/1", shapes.box, glass, parts[1]);
    }
}

void addLights(scene::Scene& scene)
{
    // Rows in the order kerb -x, kerb +x, facade -x, facade +x at each step along the street, nearest first.
    for (std::uint32_t k = 0; k < kLampsPerRow; ++k)
        for (std::uint32_t row = 0; row < 4; ++row) {
            const bool kerb = row < 2;
            const float x = side(row) * (kerb ? kPostX : kFacadeLampX);
            const float y = kerb ? kPavementTop + kPostHeight + 0.1f : kFacadeLampHeight;
            const float z = along(k, kLampsPerRow, kerb ? 0.0f : 0.5f * kLampPitch);
            scene.spotLights.push_back({.name = "lamp " + std::to_string(scene.spotLights.size() + 1),
                                        .color = kerb ? glm::vec3{1.0f, 0.78f, 0.5f} : glm::vec3{1.0f, 0.9f, 0.75f},
                                        .intensity = kerb ? 15.0f : 6.0f,
                                        .position = {x, y, z},
                                        .direction = {0.0f, -1.0f, 0.0f},
                                        .range = kerb ? 9.0f : 6.0f,
                                        .innerAngle = 0.5f,
                                        .outerAngle = 0.8f});
        }
    for (std::uint32_t i = 0; i < kStreetShopWindows; ++i)
        scene.pointLights.push_back({.name = "window " + std::to_string(i + 1),
                                     .color = kWindowColours[i % kWindowColours.size()],
                                     .intensity = 4.0f,
                                     .position = {side(i) * (kFacadeX - 0.6f), 1.6f, along(i / 2, kWindowsPerSide)},
                                     .range = 5.0f});
}

} // namespace

float streetCarDistance(float seconds) { return std::fmod(kStreetCarSpeed * seconds, 2.0f * kHalfLength); }

void driveStreetCars(scene::Scene& scene, float seconds)
{
    for (std::uint32_t k = 0; k < kStreetMovingCars; ++k) {
        const std::uint32_t i = k * (kStreetCars / kStreetMovingCars);
        // Away from the camera down the lane beside car i's kerb, from where it was parked, round to the far end.
        const glm::vec3 parked = parkedCar(i);
        float z = parked.z - streetCarDistance(seconds);
        if (z < -kHalfLength)
            z += 2.0f * kHalfLength;
        const std::array<glm::mat4, 2> parts = carParts({side(i) * kStreetLaneX, parked.y, z});
        for (std::uint32_t part = 0; part < parts.size(); ++part) {
            const std::string name = carName(i) + "/" + std::to_string(part);
            const std::optional<std::uint32_t> found = scene.findObject(name);
            if (!found)
                throw scene::SceneError("driveStreetCars: the scene has no object '" + name + "' (not the street)");
            scene::Object& object = scene.objects[*found];
            object.transform = parts[part];
            object.worldBounds = scene.meshOf(object).bounds.transformed(object.transform);
            object.mobility = scene::Mobility::Dynamic;
        }
    }
    ++scene.revision;
}

scene::Scene makeStreetScene()
{
    scene::Scene scene;
    const std::uint32_t asphalt = scene.addMaterial({.name = "asphalt", .baseColor = {0.2f, 0.2f, 0.22f, 1.0f}});
    const std::uint32_t stone = scene.addMaterial({.name = "pavement", .baseColor = {0.55f, 0.53f, 0.5f, 1.0f}});
    const std::uint32_t walls = scene.addMaterial({.name = "walls", .baseColor = {0.7f, 0.62f, 0.52f, 1.0f}});
    const std::uint32_t bark = scene.addMaterial({.name = "bark", .baseColor = {0.35f, 0.25f, 0.18f, 1.0f}});
    const std::uint32_t leaves = scene.addMaterial({.name = "leaves", .baseColor = {0.2f, 0.45f, 0.2f, 1.0f}});
    const std::uint32_t metal = scene.addMaterial(
        {.name = "metal", .baseColor = {0.3f, 0.3f, 0.32f, 1.0f}, .metallic = 1.0f, .roughness = 0.4f});
    const std::uint32_t paint = scene.addMaterial({.name = "paint", .baseColor = {0.6f, 0.12f, 0.1f, 1.0f}});
    const std::uint32_t glass = scene.addMaterial({.name = "glass", .baseColor = {0.15f, 0.18f, 0.22f, 1.0f}});
    const Shapes shapes{scene.addMesh(scene::makeBox({0.5f, 0.5f, 0.5f})),
                        scene.addMesh(scene::makeCylinder(0.2f, 1.5f, 12)),
                        scene.addMesh(scene::makeSphere(1.8f, 16, 8)),
                        scene.addMesh(scene::makeCylinder(0.08f, 0.5f * kPostHeight, 8))};

    const float groundLength = 2.0f * kHalfLength + 20.0f;
    scene.addObject("ground", shapes.box, asphalt,
                    placed({0.0f, -0.1f, 0.0f}, {2.0f * (kFacadeX + kBuildingDepth) + 10.0f, 0.2f, groundLength}));
    const float pavementWidth = kFacadeX - kRoadHalfWidth;
    for (const float s : {-1.0f, 1.0f})
        scene.addObject(s < 0.0f ? "pavement -x" : "pavement +x", shapes.box, stone,
                        placed({s * (kRoadHalfWidth + 0.5f * pavementWidth), 0.5f * kPavementTop, 0.0f},
                               {pavementWidth, kPavementTop, 2.0f * kHalfLength}));
    addBuildings(scene, shapes, walls);
    addTreesAndPosts(scene, shapes, bark, leaves, metal);
    addCars(scene, shapes, paint, glass);
    addLights(scene);
    scene.lights = {{.name = "moon",
                     .color = {0.6f, 0.7f, 1.0f},
                     .intensity = 0.08f,
                     .direction = glm::normalize(glm::vec3(-0.3f, -0.8f, 0.4f))}};
    // At eye height at the near end of the street, looking along it.
    scene.camera = scene::lookAt({2.0f, 1.8f, kHalfLength + 6.0f}, {0.0f, 2.5f, 0.0f}, glm::radians(60.0f));
    scene.camera.farPlane = 450.0f;
    return scene;
}

} // namespace penumbra::scenes
