#include "penumbra/scenes/TestScenes.hpp"

#include "penumbra/scene/MeshGenerators.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <array>
#include <cmath>

namespace penumbra::scenes {
namespace {

// Every position and size of the scene, in metres and degrees.

constexpr float kGroundHalfSize = 30.0f;

constexpr glm::vec3 kCameraPosition{0.0f, 8.0f, -20.0f};
constexpr glm::vec3 kCameraTarget{0.0f, 0.0f, 5.0f};
constexpr float kCameraFovYDegrees = 60.0f;

constexpr float kLightPitchDegrees = 50.0f;
constexpr float kFirstLightYawDegrees = 30.0f; // off the axes, so box edges do not line up with shadow texels
constexpr float kLightYawStepDegrees = 90.0f;

// Tessellation: fine enough that faceting stays below a shadow texel at the camera's distance.
constexpr std::uint32_t kSphereSegments = 48;
constexpr std::uint32_t kSphereRings = 24;
constexpr std::uint32_t kCylinderSegments = 48;

enum class Shape { Box, Sphere, Cylinder };

enum class MaterialId : std::uint32_t {
    Ground,
    Red,
    Green,
    Blue,
    White,
    Metal,
    ClipChecker,
    DitherGlass,
    NoReceive,
    Count
};

// size: box half extents; sphere (radius, -, -); cylinder (radius, half height, -).
// rotation: degrees about x, y and z, applied z first, then x, then y (Unity's Euler order).
// Standing objects have position.y equal to their half height, so they touch y = 0.
struct Placement {
    const char* name;
    Shape shape;
    glm::vec3 size;
    glm::vec3 position;
    glm::vec3 rotationDegrees;
    MaterialId material;
};

constexpr glm::vec3 kNoRotation{0.0f};

// The key light (yaw 30, pitch 50) shines along about (0.32, -0.77, 0.56); the unshadowed
// pillar stands where the floating cube's shadow falls at heights 1.5-2, so the ground
// truth says its top would be shadowed and a renderer must leave it lit.
constexpr std::array kPlacements{
    Placement{"standing cube", Shape::Box, {1.0f, 1.0f, 1.0f}, {-4.0f, 1.0f, 0.0f}, kNoRotation, MaterialId::Red},
    Placement{
        "turned cube", Shape::Box, {0.75f, 0.75f, 0.75f}, {3.5f, 0.75f, 4.0f}, {0.0f, 30.0f, 0.0f}, MaterialId::Green},
    Placement{"floating cube", Shape::Box, {0.5f, 0.5f, 0.5f}, {0.0f, 3.0f, 2.0f}, kNoRotation, MaterialId::Blue},
    Placement{
        "tumbling cube", Shape::Box, {0.6f, 0.6f, 0.6f}, {6.0f, 4.0f, 8.0f}, {35.0f, 0.0f, 20.0f}, MaterialId::White},
    Placement{
        "standing sphere", Shape::Sphere, {1.0f, 0.0f, 0.0f}, {1.5f, 1.0f, -3.0f}, kNoRotation, MaterialId::Metal},
    Placement{
        "dither sphere", Shape::Sphere, {0.75f, 0.0f, 0.0f}, {-2.5f, 2.5f, 6.0f}, kNoRotation, MaterialId::DitherGlass},
    Placement{"large sphere", Shape::Sphere, {2.0f, 0.0f, 0.0f}, {-9.0f, 2.0f, 10.0f}, kNoRotation, MaterialId::White},
    Placement{
        "standing cylinder", Shape::Cylinder, {0.5f, 1.5f, 0.0f}, {5.0f, 1.5f, -2.0f}, kNoRotation, MaterialId::Blue},
    Placement{"lying cylinder",
              Shape::Cylinder,
              {0.4f, 1.5f, 0.0f},
              {-1.0f, 1.8f, 9.0f},
              {0.0f, 0.0f, 90.0f},
              MaterialId::Red},
    Placement{"unshadowed pillar",
              Shape::Cylinder,
              {0.5f, 1.0f, 0.0f},
              {0.63f, 1.0f, 3.09f},
              kNoRotation,
              MaterialId::NoReceive},
    Placement{"tall pillar", Shape::Cylinder, {0.3f, 3.0f, 0.0f}, {8.0f, 3.0f, 2.0f}, kNoRotation, MaterialId::Green},
    Placement{"wall", Shape::Box, {4.0f, 1.5f, 0.15f}, {-1.0f, 1.5f, 14.0f}, kNoRotation, MaterialId::White},
    Placement{"clip panel", Shape::Box, {1.5f, 0.05f, 1.5f}, {3.0f, 2.5f, -7.0f}, kNoRotation, MaterialId::ClipChecker},
    // 80 units along z: from z = 30 (in view) to z = -50, 30 units behind the camera.
    Placement{"long beam", Shape::Box, {0.25f, 0.25f, 40.0f}, {-6.5f, 3.5f, -10.0f}, kNoRotation, MaterialId::Metal},
};

scene::Material material(MaterialId id)
{
    switch (id) {
    case MaterialId::Ground:
        return {.name = "ground", .baseColor = {0.6f, 0.6f, 0.6f, 1.0f}, .roughness = 0.9f};
    case MaterialId::Red:
        return {.name = "red", .baseColor = {0.8f, 0.15f, 0.1f, 1.0f}};
    case MaterialId::Green:
        return {.name = "green", .baseColor = {0.2f, 0.7f, 0.2f, 1.0f}};
    case MaterialId::Blue:
        return {.name = "blue", .baseColor = {0.15f, 0.3f, 0.8f, 1.0f}};
    case MaterialId::White:
        return {.name = "white", .baseColor = {0.9f, 0.9f, 0.9f, 1.0f}};
    case MaterialId::Metal:
        return {.name = "metal", .baseColor = {0.9f, 0.8f, 0.5f, 1.0f}, .metallic = 1.0f, .roughness = 0.3f};
    case MaterialId::ClipChecker:
        return {.name = "clip checker", .baseColor = {0.9f, 0.8f, 0.1f, 1.0f}, .caster = scene::CasterMode::Clip};
    // Alpha 0.6: about 60% of its shadow's texels survive dithering; the ground truth (fixed
    // threshold 0.5) counts it a solid caster.
    case MaterialId::DitherGlass:
        return {.name = "dither glass", .baseColor = {0.3f, 0.8f, 0.9f, 0.6f}, .caster = scene::CasterMode::Dither};
    case MaterialId::NoReceive:
        return {.name = "no receive", .baseColor = {0.9f, 0.5f, 0.1f, 1.0f}, .receiveShadows = false};
    case MaterialId::Count:
        break;
    }
    return {};
}

constexpr std::array kLightColors{glm::vec3{1.0f, 0.95f, 0.85f}, glm::vec3{1.0f, 0.35f, 0.3f},
                                  glm::vec3{0.3f, 1.0f, 0.35f}, glm::vec3{0.35f, 0.45f, 1.0f}};
constexpr std::array kLightNames{"key", "red", "green", "blue"};
constexpr std::array kLightIntensities{1.0f, 0.5f, 0.5f, 0.5f};

scene::MeshData makeMesh(const Placement& placement)
{
    switch (placement.shape) {
    case Shape::Box:
        return scene::makeBox(placement.size);
    case Shape::Sphere:
        return scene::makeSphere(placement.size.x, kSphereSegments, kSphereRings);
    case Shape::Cylinder:
        return scene::makeCylinder(placement.size.x, placement.size.y, kCylinderSegments);
    }
    return {};
}

// Rotation about y written out rather than through glm::rotate, whose y row comes out as
// c + (1 - c) and may miss 1 by an ulp: a turned standing object must keep its base at y = 0.
glm::mat4 yawRotation(float degrees)
{
    const float c = std::cos(glm::radians(degrees));
    const float s = std::sin(glm::radians(degrees));
    glm::mat4 m(1.0f);
    m[0][0] = c;
    m[0][2] = -s;
    m[2][0] = s;
    m[2][2] = c;
    return m;
}

// translate * Ry * Rx * Rz: a y-only rotation goes through yawRotation to stay exact.
glm::mat4 placementTransform(const Placement& placement)
{
    const glm::vec3 r = placement.rotationDegrees;
    glm::mat4 m = glm::translate(glm::mat4(1.0f), placement.position) * yawRotation(r.y);
    if (r.x != 0.0f)
        m = glm::rotate(m, glm::radians(r.x), glm::vec3(1.0f, 0.0f, 0.0f));
    if (r.z != 0.0f)
        m = glm::rotate(m, glm::radians(r.z), glm::vec3(0.0f, 0.0f, 1.0f));
    return m;
}

scene::Scene makeGeometry()
{
    scene::Scene scene;
    for (std::uint32_t id = 0; id < static_cast<std::uint32_t>(MaterialId::Count); ++id)
        scene.addMaterial(material(static_cast<MaterialId>(id)));
    const auto materialIndex = [](MaterialId id) { return static_cast<std::uint32_t>(id); };

    scene.addObject("ground", scene.addMesh(scene::makePlane(kGroundHalfSize)), materialIndex(MaterialId::Ground),
                    glm::mat4(1.0f));
    for (const Placement& placement : kPlacements)
        scene.addObject(placement.name, scene.addMesh(makeMesh(placement)), materialIndex(placement.material),
                        placementTransform(placement));

    scene.camera = scene::lookAt(kCameraPosition, kCameraTarget, glm::radians(kCameraFovYDegrees));
    return scene;
}

scene::DirectionalLight makeLight(std::size_t index)
{
    const float yaw = kFirstLightYawDegrees + kLightYawStepDegrees * static_cast<float>(index);
    return {.name = kLightNames[index],
            .color = kLightColors[index],
            .intensity = kLightIntensities[index],
            .direction = scene::lightDirection(glm::radians(kLightPitchDegrees), glm::radians(yaw))};
}

scene::SpotLight aimedSpot(const char* name, glm::vec3 color, glm::vec3 position, glm::vec3 target, float range)
{
    return {.name = name,
            .color = color,
            .intensity = 30.0f,
            .position = position,
            .direction = glm::normalize(target - position),
            .range = range,
            .innerAngle = glm::radians(20.0f),
            .outerAngle = glm::radians(32.0f)};
}

} // namespace

scene::Scene makeShadowTestScene()
{
    scene::Scene scene = makeGeometry();
    for (std::size_t i = 0; i < kLightNames.size(); ++i)
        scene.lights.push_back(makeLight(i));
    return scene;
}

scene::Scene makeSingleLightScene()
{
    scene::Scene scene = makeGeometry();
    scene.lights.push_back(makeLight(0));
    return scene;
}

scene::Scene makeMixedLightsScene()
{
    scene::Scene scene = makeGeometry();
    scene::DirectionalLight key = makeLight(0);
    key.intensity = 0.5f;
    scene.lights.push_back(key);
    scene.spotLights = {
        aimedSpot("spot warm", {1.0f, 0.75f, 0.5f}, {-4.0f, 6.0f, -4.0f}, {-4.0f, 0.0f, 1.0f}, 14.0f),
        aimedSpot("spot teal", {0.4f, 0.9f, 1.0f}, {6.0f, 7.0f, -1.0f}, {4.0f, 0.0f, 2.0f}, 14.0f),
        aimedSpot("spot white", {1.0f, 1.0f, 1.0f}, {0.5f, 8.0f, 3.0f}, {0.0f, 0.0f, 2.0f}, 14.0f),
    };
    scene.pointLights = {
        {.name = "bulb sphere",
         .color = {1.0f, 0.9f, 0.6f},
         .intensity = 8.0f,
         .position = {3.0f, 2.5f, -4.5f},
         .range = 9.0f},
        {.name = "bulb centre",
         .color = {0.9f, 0.6f, 1.0f},
         .intensity = 8.0f,
         .position = {-1.5f, 2.5f, 4.5f},
         .range = 9.0f},
    };
    return scene;
}

scene::Scene makePointLightRoomScene()
{
    scene::Scene scene;
    for (std::uint32_t id = 0; id < static_cast<std::uint32_t>(MaterialId::Count); ++id)
        scene.addMaterial(material(static_cast<MaterialId>(id)));
    const auto addBox = [&](const char* name, glm::vec3 halfExtents, glm::vec3 centre, MaterialId id) {
        scene.addObject(name, scene.addMesh(scene::makeBox(halfExtents)), static_cast<std::uint32_t>(id),
                        glm::translate(glm::mat4(1.0f), centre));
    };
    addBox("floor", {5.2f, 0.1f, 5.2f}, {0.0f, -0.1f, 0.0f}, MaterialId::Ground);
    addBox("ceiling", {5.2f, 0.1f, 5.2f}, {0.0f, 4.1f, 0.0f}, MaterialId::Ground);
    addBox("wall -x", {0.1f, 2.0f, 5.0f}, {-5.1f, 2.0f, 0.0f}, MaterialId::White);
    addBox("wall +x", {0.1f, 2.0f, 5.0f}, {5.1f, 2.0f, 0.0f}, MaterialId::White);
    addBox("wall -z", {5.2f, 2.0f, 0.1f}, {0.0f, 2.0f, -5.1f}, MaterialId::White);
    addBox("wall +z", {5.2f, 2.0f, 0.1f}, {0.0f, 2.0f, 5.1f}, MaterialId::White);
    addBox("crate", {0.6f, 0.6f, 0.6f}, {-1.5f, 0.6f, 2.0f}, MaterialId::Red);
    addBox("floating cube", {0.4f, 0.4f, 0.4f}, {2.0f, 2.6f, 2.0f}, MaterialId::Blue);
    scene.addObject("pillar", scene.addMesh(scene::makeCylinder(0.3f, 2.0f, kCylinderSegments)),
                    static_cast<std::uint32_t>(MaterialId::Green),
                    glm::translate(glm::mat4(1.0f), {1.8f, 2.0f, -1.0f}));
    scene.pointLights = {
        {.name = "inside", .intensity = 6.0f, .position = {0.5f, 2.0f, 0.3f}, .range = 14.0f},
        {.name = "outside", .intensity = 6.0f, .position = {0.0f, 2.0f, 5.6f}, .range = 8.0f},
    };
    scene.camera = scene::lookAt({0.0f, 3.0f, -4.6f}, {0.0f, 0.8f, 3.0f}, glm::radians(75.0f));
    return scene;
}

} // namespace penumbra::scenes
