#include "penumbra/scene/MeshGenerators.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace penumbra::scenes {
namespace {

// Every size of the scene, in metres and degrees.
constexpr float kTerrainHalfSize = 40.0f;
constexpr std::uint32_t kTerrainQuads = 35; // 35 x 35 quads: 2 450 triangles
constexpr float kTrunkHeight = 7.0f;
constexpr float kTrunkRadius = 0.25f;
constexpr std::uint32_t kBranchesPerTree = 12;
constexpr std::uint32_t kCardsPerBranch = 190; // 2 280 cards: 4 560 triangles per tree's leaves
constexpr float kCardSize = 0.6f;
constexpr std::uint32_t kLeafTextureSize = 128;
constexpr float kSunPitchDegrees = 40.0f;
constexpr float kSunYawDegrees = 30.0f;

// Where the five trees stand (x, z) and the camera among them.
constexpr std::array<glm::vec2, 5> kTrees{{{-4.0f, 6.0f}, {3.5f, 9.0f}, {-1.0f, 15.0f}, {7.0f, 3.0f}, {-8.0f, 12.0f}}};
constexpr glm::vec2 kCamera{0.5f, -2.0f};
constexpr glm::vec2 kCameraTargetOnGround{0.0f, 10.0f};
constexpr float kEyeHeight = 1.7f;

// A reproducible hash in [0, 1) (Jarzynski and Olano 2020, "Hash Functions for GPU Rendering": PCG), so the
// forest is the same with every standard library.
float random01(std::uint32_t seed)
{
    std::uint32_t state = seed * 747796405u + 2891336453u;
    std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return static_cast<float>((word >> 22u) ^ word) * (1.0f / 4294967296.0f);
}

// Rolling hills, about 1.5 m high.
float terrainHeight(float x, float z)
{
    return 0.8f * std::sin(0.11f * x + 0.4f) * std::cos(0.09f * z) + 0.5f * std::sin(0.23f * x + 0.31f * z) +
           0.2f * std::cos(0.53f * z - 0.17f * x);
}

glm::vec3 terrainNormal(float x, float z)
{
    constexpr float h = 0.05f;
    const float dx = (terrainHeight(x + h, z) - terrainHeight(x - h, z)) / (2.0f * h);
    const float dz = (terrainHeight(x, z + h) - terrainHeight(x, z - h)) / (2.0f * h);
    return glm::normalize(glm::vec3(-dx, 1.0f, -dz));
}

scene::MeshData makeTerrain()
{
    scene::MeshData mesh;
    const std::uint32_t n = kTerrainQuads + 1;
    for (std::uint32_t j = 0; j < n; ++j)
        for (std::uint32_t i = 0; i < n; ++i) {
            const float u = static_cast<float>(i) / kTerrainQuads, v = static_cast<float>(j) / kTerrainQuads;
            const float x = (2.0f * u - 1.0f) * kTerrainHalfSize, z = (2.0f * v - 1.0f) * kTerrainHalfSize;
            mesh.vertices.push_back({{x, terrainHeight(x, z), z}, terrainNormal(x, z), {8.0f * u, 8.0f * v}});
        }
    for (std::uint32_t j = 0; j < kTerrainQuads; ++j)
        for (std::uint32_t i = 0; i < kTerrainQuads; ++i) {
            const std::uint32_t a = j * n + i, b = a + 1, c = a + n, d = c + 1;
            // Counter-clockwise seen from above (+y).
            mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
        }
    updateBounds(mesh);
    return mesh;
}

void append(scene::MeshData& into, const scene::MeshData& part, const glm::mat4& transform)
{
    const auto first = static_cast<std::uint32_t>(into.vertices.size());
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(transform)));
    for (const scene::Vertex& v : part.vertices)
        into.vertices.push_back(
            {glm::vec3(transform * glm::vec4(v.position, 1.0f)), glm::normalize(normalMatrix * v.normal), v.uv});
    for (const std::uint32_t index : part.indices)
        into.indices.push_back(first + index);
}

// One leaf card: a unit quad in the xy plane facing +z, uv over the whole leaf texture.
scene::MeshData makeCard()
{
    scene::MeshData card;
    const glm::vec3 normal{0.0f, 0.0f, 1.0f};
    card.vertices = {{{-0.5f, -0.5f, 0.0f}, normal, {0.0f, 1.0f}},
                     {{0.5f, -0.5f, 0.0f}, normal, {1.0f, 1.0f}},
                     {{0.5f, 0.5f, 0.0f}, normal, {1.0f, 0.0f}},
                     {{-0.5f, 0.5f, 0.0f}, normal, {0.0f, 0.0f}}};
    card.indices = {0, 1, 2, 0, 2, 3};
    return card;
}

struct Tree {
    scene::MeshData wood;
    scene::MeshData leaves;
};

// A trunk, branches leaning out from its upper half, and leaf cards in a cloud around each branch's end.
Tree makeTree(std::uint32_t seed)
{
    Tree tree;
    append(tree.wood, scene::makeCylinder(kTrunkRadius, 0.5f * kTrunkHeight, 10),
           glm::translate(glm::mat4(1.0f), {0.0f, 0.5f * kTrunkHeight, 0.0f}));
    const scene::MeshData branch = scene::makeCylinder(0.07f, 1.0f, 6);
    const scene::MeshData card = makeCard();
    for (std::uint32_t b = 0; b < kBranchesPerTree; ++b) {
        const std::uint32_t s = seed * 1000u + b * 10u;
        const float height = kTrunkHeight * (0.45f + 0.5f * random01(s));
        const float yaw = glm::two_pi<float>() * (static_cast<float>(b) + random01(s + 1)) / kBranchesPerTree;
        const float lean = glm::radians(40.0f + 30.0f * random01(s + 2));
        const float length = 1.6f + 1.2f * random01(s + 3);
        const glm::mat4 orientation =
            glm::rotate(glm::rotate(glm::mat4(1.0f), yaw, {0.0f, 1.0f, 0.0f}), lean, {1.0f, 0.0f, 0.0f});
        const glm::mat4 base = glm::translate(glm::mat4(1.0f), {0.0f, height, 0.0f}) * orientation;
        append(tree.wood, branch,
               base * glm::translate(glm::mat4(1.0f), {0.0f, 0.5f * length, 0.0f}) *
                   glm::scale(glm::mat4(1.0f), {1.0f, 0.5f * length, 1.0f}));
        const glm::vec3 tip = glm::vec3(base * glm::vec4(0.0f, length, 0.0f, 1.0f));
        for (std::uint32_t c = 0; c < kCardsPerBranch; ++c) {
            const std::uint32_t r = s * 977u + c * 7u;
            // A point in an ellipsoid of 1.3 x 0.9 x 1.3 around the tip, a random orientation, a size of 0.8 to 1.2.
            const glm::vec3 offset{2.0f * random01(r) - 1.0f, 2.0f * random01(r + 1) - 1.0f,
                                   2.0f * random01(r + 2) - 1.0f};
            const glm::vec3 position = tip + glm::vec3(1.3f, 0.9f, 1.3f) * offset * std::cbrt(random01(r + 3));
            const glm::mat4 turn =
                glm::rotate(glm::rotate(glm::mat4(1.0f), glm::two_pi<float>() * random01(r + 4), {0.0f, 1.0f, 0.0f}),
                            glm::radians(-60.0f + 120.0f * random01(r + 5)), {1.0f, 0.0f, 0.0f});
            const float size = kCardSize * (0.8f + 0.4f * random01(r + 6));
            append(tree.leaves, card,
                   glm::translate(glm::mat4(1.0f), position) * turn * glm::scale(glm::mat4(1.0f), glm::vec3(size)));
        }
    }
    updateBounds(tree.wood);
    updateBounds(tree.leaves);
    return tree;
}

// Four leaves on a card, each an ellipse pointed at both ends around its midrib, drawn in alpha: 1 inside, 0
// outside, with a one-texel ramp so that bilinear filtering gives a smooth cut-out edge.
scene::TextureImage makeLeafTexture()
{
    scene::TextureImage image{"leaves", kLeafTextureSize, kLeafTextureSize,
                              std::vector<std::uint8_t>(std::size_t(kLeafTextureSize) * kLeafTextureSize * 4)};
    struct Leaf {
        glm::vec2 centre;
        float angle, length, width;
    };
    constexpr std::array<Leaf, 4> leaves{{{{0.3f, 0.3f}, 0.6f, 0.26f, 0.11f},
                                          {{0.7f, 0.32f}, -0.5f, 0.24f, 0.1f},
                                          {{0.32f, 0.72f}, 2.4f, 0.25f, 0.1f},
                                          {{0.7f, 0.7f}, -2.2f, 0.27f, 0.12f}}};
    for (std::uint32_t y = 0; y < kLeafTextureSize; ++y)
        for (std::uint32_t x = 0; x < kLeafTextureSize; ++x) {
            const glm::vec2 p = (glm::vec2(x, y) + 0.5f) / static_cast<float>(kLeafTextureSize);
            float inside = -1e9f; // texels inside the nearest leaf, positive inside
            for (const Leaf& leaf : leaves) {
                const glm::vec2 d = p - leaf.centre;
                const float along = std::cos(leaf.angle) * d.x + std::sin(leaf.angle) * d.y;
                const float across = -std::sin(leaf.angle) * d.x + std::cos(leaf.angle) * d.y;
                const float t = std::min(std::abs(along) / leaf.length, 1.0f);
                const float halfWidth = leaf.width * (1.0f - t * t); // pointed at both ends
                inside = std::max(inside, (halfWidth - std::abs(across)) * kLeafTextureSize);
            }
            const float alpha = std::clamp(inside + 0.5f, 0.0f, 1.0f);
            std::uint8_t* texel = &image.rgba[4 * (std::size_t(y) * kLeafTextureSize + x)];
            texel[0] = 90;
            texel[1] = static_cast<std::uint8_t>(150 + 40 * random01(y * kLeafTextureSize + x));
            texel[2] = 60;
            texel[3] = static_cast<std::uint8_t>(std::lround(255.0f * alpha));
        }
    return image;
}

} // namespace

scene::Scene makeForestScene()
{
    scene::Scene scene;
    const std::uint32_t ground =
        scene.addMaterial({.name = "grass", .baseColor = {0.25f, 0.4f, 0.15f, 1.0f}, .roughness = 0.9f});
    const std::uint32_t bark =
        scene.addMaterial({.name = "bark", .baseColor = {0.3f, 0.2f, 0.12f, 1.0f}, .roughness = 0.8f});
    const auto leafTexture = static_cast<std::uint32_t>(scene.textures.size());
    scene.textures.push_back(makeLeafTexture());
    // Leaf cards are seen and lit from both sides, and cast from both.
    const std::uint32_t leaves = scene.addMaterial({.name = "leaves",
                                                    .baseColor = {1.0f, 1.0f, 1.0f, 1.0f},
                                                    .roughness = 0.6f,
                                                    .alphaCutoff = 0.5f,
                                                    .caster = scene::CasterMode::Clip,
                                                    .doubleSided = true,
                                                    .textures = {scene::MaterialTexture{.image = leafTexture}}});
    scene.addObject("terrain", scene.addMesh(makeTerrain()), ground, glm::mat4(1.0f));
    for (std::uint32_t i = 0; i < kTrees.size(); ++i) {
        Tree tree = makeTree(i + 1);
        const glm::vec2 at = kTrees[i];
        // Sunk a little, so the trunk meets the slope everywhere around it.
        const glm::mat4 place = glm::translate(glm::mat4(1.0f), {at.x, terrainHeight(at.x, at.y) - 0.3f, at.y});
        const std::string name = "tree " + std::to_string(i + 1);
        scene.addObject(name + " wood", scene.addMesh(std::move(tree.wood)), bark, place);
        scene.addObject(name + " leaves", scene.addMesh(std::move(tree.leaves)), leaves, place);
    }
    scene::DirectionalLight sun;
    sun.name = "sun";
    sun.color = {1.0f, 0.96f, 0.88f};
    sun.intensity = 3.0f;
    sun.direction = scene::lightDirection(glm::radians(kSunPitchDegrees), glm::radians(kSunYawDegrees));
    scene.lights.push_back(sun);
    const glm::vec3 eye{kCamera.x, terrainHeight(kCamera.x, kCamera.y) + kEyeHeight, kCamera.y};
    const glm::vec3 target{kCameraTargetOnGround.x,
                           terrainHeight(kCameraTargetOnGround.x, kCameraTargetOnGround.y) + 3.0f,
                           kCameraTargetOnGround.y};
    scene.camera = scene::lookAt(eye, target, glm::radians(60.0f));
    scene.camera.farPlane = 150.0f;
    scene.validate();
    return scene;
}

} // namespace penumbra::scenes
