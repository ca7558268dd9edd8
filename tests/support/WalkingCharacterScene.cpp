#include "GltfAnimationScenes.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace penumbra::testing {
namespace {

// The skeleton, in Skin::joints order. Joints sit where their bone starts; the rest pose has no rotations, so each
// inverse bind matrix is a translation by minus the joint's position.
enum Joint : std::uint8_t {
    Hips,
    Spine,
    Head,
    ShoulderL,
    ElbowL,
    ShoulderR,
    ElbowR,
    LegL,
    KneeL,
    LegR,
    KneeR,
    kJoints
};

struct JointDesc {
    const char* name;
    int parent; // a Joint, -1 for the root
    glm::vec3 position; // in the rest pose, in the scene
};

constexpr std::array<JointDesc, kJoints> kSkeleton{{
    {"hips", -1, {0.0f, 0.95f, 0.0f}},
    {"spine", Hips, {0.0f, 1.02f, 0.0f}},
    {"head", Spine, {0.0f, 1.47f, 0.0f}},
    {"shoulder.L", Spine, {0.23f, 1.45f, 0.0f}},
    {"elbow.L", ShoulderL, {0.23f, 1.17f, 0.0f}},
    {"shoulder.R", Spine, {-0.23f, 1.45f, 0.0f}},
    {"elbow.R", ShoulderR, {-0.23f, 1.17f, 0.0f}},
    {"leg.L", Hips, {0.09f, 0.9f, 0.0f}},
    {"knee.L", LegL, {0.09f, 0.5f, 0.0f}},
    {"leg.R", Hips, {-0.09f, 0.9f, 0.0f}},
    {"knee.R", LegR, {-0.09f, 0.5f, 0.0f}},
}};

// Linear colours of the clothes and skin (COLOR_0 multiplies the white base colour).
constexpr glm::vec3 kSkin{0.8f, 0.55f, 0.4f};
constexpr glm::vec3 kShirt{0.15f, 0.3f, 0.7f};
constexpr glm::vec3 kTrousers{0.2f, 0.2f, 0.25f};
constexpr glm::vec3 kShoes{0.05f, 0.05f, 0.05f};

// A box of the figure, drawn by `joint`. Along `axis` (1: y, 2: z) it is cut into rings; a ring within kBlend of where
// the box meets a neighbour (the joint between them: the one of the two that is the other's child) takes up to half
// its weight from the neighbour's joint, so that the two boxes share their weights there and bend together.
struct Part {
    Joint joint;
    glm::vec3 min, max;
    glm::vec3 colour;
    int axis = 1;
    std::array<int, 2> neighbours{-1, -1}; // joints, -1: none
};

constexpr float kBlend = 0.08f;
constexpr float kRingSpacing = 0.04f;

// Left parts; the right ones mirror them in x.
constexpr std::array<Part, 5> kLeftParts{{
    {ShoulderL, {0.18f, 1.17f, -0.05f}, {0.28f, 1.47f, 0.05f}, kShirt, 1, {Spine, ElbowL}},
    {ElbowL, {0.185f, 0.86f, -0.045f}, {0.275f, 1.17f, 0.045f}, kSkin, 1, {ShoulderL, -1}},
    {LegL, {0.02f, 0.5f, -0.07f}, {0.16f, 0.9f, 0.07f}, kTrousers, 1, {Hips, KneeL}},
    {KneeL, {0.03f, 0.06f, -0.06f}, {0.15f, 0.5f, 0.06f}, kTrousers, 1, {LegL, -1}},
    {KneeL, {0.03f, 0.0f, -0.06f}, {0.15f, 0.06f, 0.2f}, kShoes, 2, {-1, -1}},
}};

int mirrored(int joint)
{
    switch (joint) {
    case ShoulderL:
        return ShoulderR;
    case ElbowL:
        return ElbowR;
    case LegL:
        return LegR;
    case KneeL:
        return KneeR;
    default:
        return joint;
    }
}

std::vector<Part> parts()
{
    std::vector<Part> all{
        {Hips, {-0.17f, 0.82f, -0.1f}, {0.17f, 1.02f, 0.1f}, kTrousers, 1, {Spine, -1}},
        {Spine, {-0.17f, 1.02f, -0.1f}, {0.17f, 1.47f, 0.1f}, kShirt, 1, {Hips, -1}},
        {Head, {-0.1f, 1.47f, -0.11f}, {0.1f, 1.75f, 0.11f}, kSkin},
    };
    for (const Part& left : kLeftParts) {
        all.push_back(left);
        Part right = left;
        right.joint = Joint(mirrored(left.joint));
        right.min.x = -left.max.x;
        right.max.x = -left.min.x;
        right.neighbours = {mirrored(left.neighbours[0]), mirrored(left.neighbours[1])};
        all.push_back(right);
    }
    return all;
}

struct SkinnedMesh {
    std::vector<glm::vec3> positions, normals, colours;
    std::vector<std::uint8_t> joints; // 4 per vertex
    std::vector<float> weights; // 4 per vertex
    std::vector<std::uint16_t> indices;

    void vertex(const glm::vec3& p, const glm::vec3& n, const Part& part)
    {
        positions.push_back(p);
        normals.push_back(n);
        colours.push_back(part.colour);
        // Half the weight at the joint between the two boxes, none kBlend away from it.
        const auto share = [&](int neighbour) {
            if (neighbour < 0)
                return 0.0f;
            const int between = kSkeleton[std::size_t(neighbour)].parent == part.joint ? neighbour : part.joint;
            const float at = kSkeleton[std::size_t(between)].position[part.axis];
            return 0.5f * std::max(0.0f, 1.0f - std::abs(p[part.axis] - at) / kBlend);
        };
        const float first = share(part.neighbours[0]), second = share(part.neighbours[1]);
        joints.insert(joints.end(), {std::uint8_t(part.joint), std::uint8_t(std::max(part.neighbours[0], 0)),
                                     std::uint8_t(std::max(part.neighbours[1], 0)), 0});
        weights.insert(weights.end(), {1.0f - first - second, first, second, 0.0f});
    }

    // Two triangles over four vertices from `first`, turned to face `outward`.
    void quad(std::uint16_t first, const glm::vec3& outward)
    {
        const auto triangle = [&](std::uint16_t a, std::uint16_t b, std::uint16_t c) {
            if (glm::dot(glm::cross(positions[b] - positions[a], positions[c] - positions[a]), outward) < 0.0f)
                std::swap(b, c);
            indices.insert(indices.end(), {a, b, c});
        };
        triangle(first, std::uint16_t(first + 1), std::uint16_t(first + 2));
        triangle(first, std::uint16_t(first + 2), std::uint16_t(first + 3));
    }

    // The box's four sides as strips of quads between rings (flat normals), and its two ends.
    void box(const Part& part)
    {
        // The cross-section is in x and the other axis.
        const int a = part.axis, u = 0, v = a == 1 ? 2 : 1;
        const float length = part.max[a] - part.min[a];
        const int rings = std::max(1, int(std::ceil(length / kRingSpacing)));
        // The cross-section's corners counter-clockwise in (u, v).
        const std::array<glm::vec2, 4> corners{glm::vec2(part.max[u], part.max[v]), glm::vec2(part.min[u], part.max[v]),
                                               glm::vec2(part.min[u], part.min[v]),
                                               glm::vec2(part.max[u], part.min[v])};
        const auto point = [&](const glm::vec2& corner, float along) {
            glm::vec3 p;
            p[u] = corner.x;
            p[v] = corner.y;
            p[a] = along;
            return p;
        };
        const glm::vec3 centre = 0.5f * (part.min + part.max);
        for (int side = 0; side < 4; ++side) {
            const glm::vec2 c0 = corners[std::size_t(side)], c1 = corners[std::size_t(side + 1) % 4];
            glm::vec3 normal = point(0.5f * (c0 + c1), centre[a]) - centre;
            normal = glm::normalize(normal);
            for (int ring = 0; ring < rings; ++ring) {
                const float lo = part.min[a] + length * float(ring) / float(rings);
                const float hi = part.min[a] + length * float(ring + 1) / float(rings);
                const auto first = std::uint16_t(positions.size());
                vertex(point(c0, lo), normal, part);
                vertex(point(c1, lo), normal, part);
                vertex(point(c1, hi), normal, part);
                vertex(point(c0, hi), normal, part);
                quad(first, normal);
            }
        }
        for (const float end : {part.min[a], part.max[a]}) {
            glm::vec3 normal(0.0f);
            normal[a] = end == part.min[a] ? -1.0f : 1.0f;
            const auto first = std::uint16_t(positions.size());
            for (const glm::vec2& corner : corners)
                vertex(point(corner, end), normal, part);
            quad(first, normal);
        }
    }
};

glm::quat about(const glm::vec3& axis, float degrees) { return glm::angleAxis(glm::radians(degrees), axis); }

// The walk's local rotation of `joint` at `phase` (0 to 1 over a cycle; the left leg passes under the hips moving
// forward at 0). The left leg is forward at 0.25, the right at 0.75; each knee bends most mid-swing.
glm::quat walkRotation(Joint joint, float phase)
{
    constexpr float kLegSwing = 25.0f, kArmSwing = 20.0f, kKneeBend = 45.0f, kHipTurn = 6.0f;
    const float s = std::sin(2.0f * std::numbers::pi_v<float> * phase);
    const float c = std::cos(2.0f * std::numbers::pi_v<float> * phase);
    const glm::vec3 x(1.0f, 0.0f, 0.0f), y(0.0f, 1.0f, 0.0f);
    // About +x a positive angle swings a hanging limb backwards (towards -z).
    switch (joint) {
    case Hips:
        return about(y, -kHipTurn * s); // the left hip forward with the left leg
    case Spine:
        return about(y, 2.0f * kHipTurn * s); // the shoulders turn against the hips
    case LegL:
        return about(x, -kLegSwing * s);
    case LegR:
        return about(x, kLegSwing * s);
    case KneeL:
        return about(x, 5.0f + kKneeBend * std::max(0.0f, c));
    case KneeR:
        return about(x, 5.0f + kKneeBend * std::max(0.0f, -c));
    case ShoulderL:
        return about(x, kArmSwing * s);
    case ShoulderR:
        return about(x, -kArmSwing * s);
    case ElbowL:
        return about(x, -10.0f - 20.0f * std::max(0.0f, -s));
    case ElbowR:
        return about(x, -10.0f - 20.0f * std::max(0.0f, s));
    default:
        return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    }
}

// The hips' height: lowered by what the straight leg's swing lifts its foot (leg length 0.9 from joint to sole).
float hipsHeight(float phase)
{
    const float swing = glm::radians(25.0f) * std::sin(2.0f * std::numbers::pi_v<float> * phase);
    return kSkeleton[Hips].position.y - 0.9f * (1.0f - std::cos(swing));
}

// The node rotation that turns its -z (where glTF lights and cameras look) towards `direction`.
nlohmann::json facing(const glm::vec3& direction)
{
    const glm::quat q = glm::quatLookAt(glm::normalize(direction), glm::vec3(0.0f, 1.0f, 0.0f));
    return {q.x, q.y, q.z, q.w};
}

} // namespace

GltfBuilder walkingCharacterScene()
{
    GltfBuilder b;
    SkinnedMesh mesh;
    for (const Part& part : parts())
        mesh.box(part);
    const std::size_t count = mesh.positions.size();
    const int position = b.addPositions(mesh.positions);
    const int normal = b.addNormals(mesh.normals);
    const int colour =
        addFloatAccessor(b, std::span<const float>(reinterpret_cast<const float*>(mesh.colours.data()), 3 * count),
                         "VEC3");
    const int joint = b.addAccessor(mesh.joints, count, "VEC4", Component::UnsignedByte);
    const int weight = b.addAccessor(bytesOf(std::span<const float>(mesh.weights)), count, "VEC4", Component::Float);
    const int index = b.addAccessor(bytesOf(std::span<const std::uint16_t>(mesh.indices)), mesh.indices.size(),
                                    "SCALAR", Component::UnsignedShort);
    const int material =
        b.add("materials",
              {{"name", "figure"}, {"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 0.7}}}});
    const int figure = b.add("meshes", {{"name", "figure"},
                                        {"primitives",
                                         {{{"attributes",
                                            {{"POSITION", position},
                                             {"NORMAL", normal},
                                             {"COLOR_0", colour},
                                             {"JOINTS_0", joint},
                                             {"WEIGHTS_0", weight}}},
                                           {"indices", index},
                                           {"material", material}}}}});

    // Joint nodes in skeleton order, then their children lists; the translations are relative to the parent.
    std::array<int, kJoints> nodes{};
    for (std::size_t j = 0; j < kJoints; ++j) {
        const JointDesc& desc = kSkeleton[j];
        const glm::vec3 offset =
            desc.position - (desc.parent < 0 ? glm::vec3(0.0f) : kSkeleton[std::size_t(desc.parent)].position);
        nodes[j] = b.add("nodes", {{"name", desc.name}, {"translation", {offset.x, offset.y, offset.z}}});
    }
    for (std::size_t j = 0; j < kJoints; ++j)
        if (kSkeleton[j].parent >= 0)
            b.json()["nodes"][std::size_t(nodes[std::size_t(kSkeleton[j].parent)])]["children"].push_back(nodes[j]);
    b.addRoot(nodes[Hips]);
    std::vector<float> inverseBind;
    for (const JointDesc& desc : kSkeleton)
        inverseBind.insert(inverseBind.end(), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -desc.position.x, -desc.position.y,
                                               -desc.position.z, 1});
    b.add("skins", {{"name", "figure"},
                    {"joints", nodes},
                    {"skeleton", nodes[Hips]},
                    {"inverseBindMatrices", addFloatAccessor(b, inverseBind, "MAT4")}});
    b.addRoot(b.add("nodes", {{"name", "figure"}, {"mesh", figure}, {"skin", 0}}));

    // 16 keys a second and a 17th equal to the first, so that the loop closes.
    constexpr int kKeys = 16;
    std::vector<float> times;
    for (int k = 0; k <= kKeys; ++k)
        times.push_back(float(k) / float(kKeys));
    nlohmann::json samplers = nlohmann::json::array();
    nlohmann::json channels = nlohmann::json::array();
    for (std::size_t j = 0; j < kJoints; ++j) {
        if (j == Head)
            continue;
        std::vector<float> rotations;
        for (const float t : times) {
            const glm::quat q = walkRotation(Joint(j), t);
            rotations.insert(rotations.end(), {q.x, q.y, q.z, q.w});
        }
        channels.push_back({{"sampler", addSampler(b, samplers, times, rotations, "VEC4", "LINEAR")},
                            {"target", {{"node", nodes[j]}, {"path", "rotation"}}}});
    }
    std::vector<float> hips;
    for (const float t : times)
        hips.insert(hips.end(), {0.0f, hipsHeight(t), 0.0f});
    channels.push_back({{"sampler", addSampler(b, samplers, times, hips, "VEC3", "LINEAR")},
                        {"target", {{"node", nodes[Hips]}, {"path", "translation"}}}});
    b.add("animations", {{"name", "walk"}, {"channels", channels}, {"samplers", samplers}});

    const int groundMesh = addCubeMesh(b, "ground", -1);
    b.addRoot(
        b.add("nodes",
              {{"name", "ground"}, {"mesh", groundMesh}, {"translation", {0, -0.05, 0}}, {"scale", {4, 0.05, 4}}}));
    b.useExtension("KHR_lights_punctual");
    b.json()["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"name", "sun"}, {"type", "directional"}, {"intensity", 3.0}},
        {{"name", "spot"},
         {"type", "spot"},
         {"intensity", 40.0},
         {"range", 12.0},
         {"spot", {{"innerConeAngle", 0.3}, {"outerConeAngle", 0.45}}}}};
    // The sun 35 degrees up from the figure's left and a little in front: the shadow falls to the right and back,
    // where the legs' swing along z shows in it.
    b.addRoot(b.add("nodes", {{"name", "sun"},
                              {"rotation", facing({-1.0f, -0.8f, -0.4f})},
                              {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}));
    const glm::vec3 spot(1.2f, 3.0f, 2.5f);
    b.addRoot(b.add("nodes", {{"name", "spot"},
                              {"translation", {spot.x, spot.y, spot.z}},
                              {"rotation", facing(glm::vec3(0.0f, 0.8f, 0.0f) - spot)},
                              {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}}));
    b.add("cameras", {{"name", "front"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}});
    const glm::vec3 eye(1.5f, 2.2f, 4.2f);
    b.addRoot(b.add("nodes", {{"name", "front"},
                              {"camera", 0},
                              {"translation", {eye.x, eye.y, eye.z}},
                              {"rotation", facing(glm::vec3(-0.8f, 0.6f, -0.6f) - eye)}}));
    return b;
}

} // namespace penumbra::testing
