#include "GltfAnimationScenes.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace penumbra::testing {
namespace {

std::size_t components(const std::string& type)
{
    return type == "SCALAR" ? 1 : type == "MAT4" ? 16 : std::size_t(type.back() - '0');
}

// The bar's rings: 4 corners at half width 0.1, counter-clockwise seen from above.
constexpr std::array<glm::vec2, 4> kCorners{glm::vec2(0.1f, 0.1f), glm::vec2(0.1f, -0.1f), glm::vec2(-0.1f, -0.1f),
                                            glm::vec2(-0.1f, 0.1f)};

// Triangles of the bar's sides between rings and its top cap, each wound counter-clockwise seen from outside.
std::vector<std::uint16_t> barIndices(const std::vector<glm::vec3>& positions)
{
    std::vector<std::uint16_t> indices;
    const auto triangle = [&](std::uint16_t a, std::uint16_t b, std::uint16_t c, const glm::vec3& outward) {
        const glm::vec3 n = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
        if (glm::dot(n, outward) < 0.0f)
            std::swap(b, c);
        indices.insert(indices.end(), {a, b, c});
    };
    for (std::uint16_t ring = 0; ring < 2; ++ring)
        for (std::uint16_t i = 0; i < 4; ++i) {
            const auto j = std::uint16_t((i + 1) % 4);
            const std::uint16_t a = std::uint16_t(ring * 4 + i), b = std::uint16_t(ring * 4 + j);
            const glm::vec3 outward = glm::vec3(kCorners[i].x + kCorners[j].x, 0.0f, kCorners[i].y + kCorners[j].y);
            triangle(a, b, std::uint16_t(b + 4), outward);
            triangle(a, std::uint16_t(b + 4), std::uint16_t(a + 4), outward);
        }
    triangle(8, 9, 10, glm::vec3(0.0f, 1.0f, 0.0f));
    triangle(8, 10, 11, glm::vec3(0.0f, 1.0f, 0.0f));
    return indices;
}

void addLightAndCamera(GltfBuilder& b, const glm::vec3& cameraPosition)
{
    b.useExtension("KHR_lights_punctual");
    b.json()["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"name", "sun"}, {"type", "directional"}, {"intensity", 3.0}}};
    // Straight down, turned a little about x so the bar's shadow falls beside it.
    b.addRoot(b.add("nodes", {{"name", "sun"},
                              {"rotation", {-0.6427876, 0, 0, 0.7660444}},
                              {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}));
    b.add("cameras", {{"name", "side"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.1}}}});
    b.addRoot(b.add("nodes", {{"name", "side"},
                              {"camera", 0},
                              {"translation", {cameraPosition.x, cameraPosition.y, cameraPosition.z}}}));
}

} // namespace

int addFloatAccessor(GltfBuilder& builder, std::span<const float> values, const std::string& type)
{
    const std::size_t n = components(type);
    std::vector<float> lo(n, std::numeric_limits<float>::max()), hi(n, -std::numeric_limits<float>::max());
    for (std::size_t i = 0; i < values.size(); ++i) {
        lo[i % n] = std::min(lo[i % n], values[i]);
        hi[i % n] = std::max(hi[i % n], values[i]);
    }
    const int accessor = builder.addAccessor(bytesOf(values), values.size() / n, type, Component::Float);
    builder.json()["accessors"][std::size_t(accessor)]["min"] = lo;
    builder.json()["accessors"][std::size_t(accessor)]["max"] = hi;
    return accessor;
}

int addSampler(GltfBuilder& b, nlohmann::json& samplers, std::span<const float> times, std::span<const float> values,
               const std::string& type, const std::string& interpolation)
{
    samplers.push_back({{"input", addFloatAccessor(b, times, "SCALAR")},
                        {"output", addFloatAccessor(b, values, type)},
                        {"interpolation", interpolation}});
    return int(samplers.size()) - 1;
}

GltfBuilder twoBoneBendScene(BendWeights weights)
{
    GltfBuilder b;
    std::vector<glm::vec3> positions, normals;
    for (int ring = 0; ring < 3; ++ring)
        for (const glm::vec2& corner : kCorners) {
            positions.emplace_back(corner.x, float(ring), corner.y);
            normals.push_back(glm::normalize(glm::vec3(corner.x, 0.0f, corner.y)));
        }
    const std::vector<std::uint16_t> indices = barIndices(positions);
    std::vector<std::uint8_t> joints;
    std::vector<float> floatWeights;
    for (int ring = 0; ring < 3; ++ring)
        for (int i = 0; i < 4; ++i) {
            joints.insert(joints.end(), {0, 1, 0, 0});
            const float elbow = 0.5f * float(ring);
            floatWeights.insert(floatWeights.end(), {1.0f - elbow, elbow, 0.0f, 0.0f});
        }
    const int position = b.addPositions(positions);
    const int normal = b.addNormals(normals);
    const int index = b.addAccessor(bytesOf(std::span<const std::uint16_t>(indices)), indices.size(), "SCALAR",
                                    Component::UnsignedShort);
    const int joint = b.addAccessor(joints, positions.size(), "VEC4", Component::UnsignedByte);
    int weight = 0;
    if (weights == BendWeights::Float) {
        weight =
            b.addAccessor(bytesOf(std::span<const float>(floatWeights)), positions.size(), "VEC4", Component::Float);
    } else {
        const float total = weights == BendWeights::UnsignedByte ? 255.0f : 200.0f;
        std::vector<std::uint8_t> bytes;
        for (const float w : floatWeights)
            bytes.push_back(std::uint8_t(std::lround(w * total)));
        weight = b.addAccessor(bytes, positions.size(), "VEC4", Component::UnsignedByte, true);
    }
    const int material =
        b.add("materials",
              {{"name", "bar"},
               {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.3, 0.1, 1.0}}, {"metallicFactor", 0}}}});
    const int mesh =
        b.add("meshes", {{"name", "bar"},
                         {"primitives",
                          {{{"attributes",
                             {{"POSITION", position}, {"NORMAL", normal}, {"JOINTS_0", joint}, {"WEIGHTS_0", weight}}},
                            {"indices", index},
                            {"material", material}}}}});
    const int elbow = b.add("nodes", {{"name", "elbow"}, {"translation", {0, 1, 0}}});
    const int root = b.add("nodes", {{"name", "root"}, {"children", {elbow}}});
    b.addRoot(root);
    const std::array<float, 32> inverseBind{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  0, 1,
                                            1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1};
    b.add("skins", {{"name", "arm"},
                    {"joints", {root, elbow}},
                    {"skeleton", root},
                    {"inverseBindMatrices", addFloatAccessor(b, inverseBind, "MAT4")}});
    b.addRoot(b.add("nodes", {{"name", "bar"}, {"mesh", mesh}, {"skin", 0}}));
    const int groundMesh = addCubeMesh(b, "ground", -1);
    b.addRoot(b.add("nodes",
                    {{"name", "ground"}, {"mesh", groundMesh}, {"translation", {0, -0.1, 0}}, {"scale", {3, 0.1, 3}}}));

    nlohmann::json bendSamplers = nlohmann::json::array();
    const std::array<float, 2> bendTimes{0.0f, 1.0f};
    const std::array<float, 8> bendTurns{0, 0, 0, 1, 0, 0, 0.70710678f, 0.70710678f};
    addSampler(b, bendSamplers, bendTimes, bendTurns, "VEC4", "LINEAR");
    b.add("animations", {{"name", "bend"},
                         {"channels", {{{"sampler", 0}, {"target", {{"node", elbow}, {"path", "rotation"}}}}}},
                         {"samplers", bendSamplers}});
    nlohmann::json liftSamplers = nlohmann::json::array();
    const std::array<float, 2> liftTimes{0.0f, 0.5f};
    const std::array<float, 6> lifts{0, 0, 0, 0, 1, 0};
    addSampler(b, liftSamplers, liftTimes, lifts, "VEC3", "STEP");
    b.add("animations", {{"name", "lift"},
                         {"channels", {{{"sampler", 0}, {"target", {{"node", root}, {"path", "translation"}}}}}},
                         {"samplers", liftSamplers}});
    addLightAndCamera(b, glm::vec3(0.0f, 1.2f, 5.0f));
    return b;
}

GltfBuilder morphScene()
{
    GltfBuilder b;
    const int mesh = addQuadMesh(b, "quad", -1);
    const std::array<glm::vec3, 4> first{glm::vec3(0, 0, 1), glm::vec3(0), glm::vec3(0), glm::vec3(0)};
    const std::array<glm::vec3, 4> second{glm::vec3(0, 1, 0), glm::vec3(0, 1, 0), glm::vec3(0, 1, 0),
                                          glm::vec3(0, 1, 0)};
    nlohmann::json& primitive = b.json()["meshes"][std::size_t(mesh)]["primitives"][0];
    primitive["targets"] = {{{"POSITION", b.addPositions(first)}}, {{"POSITION", b.addPositions(second)}}};
    b.json()["meshes"][std::size_t(mesh)]["weights"] = {0.5, 0.0};
    const int node = b.add("nodes", {{"name", "quad"}, {"mesh", mesh}});
    b.addRoot(node);
    nlohmann::json samplers = nlohmann::json::array();
    const std::array<float, 2> times{0.0f, 2.0f};
    const std::array<float, 4> weights{0.0f, 0.0f, 1.0f, 0.5f};
    addSampler(b, samplers, times, weights, "SCALAR", "LINEAR");
    b.add("animations", {{"name", "morph"},
                         {"channels", {{{"sampler", 0}, {"target", {{"node", node}, {"path", "weights"}}}}}},
                         {"samplers", samplers}});
    return b;
}

GltfBuilder keyframeScene()
{
    GltfBuilder b;
    const int cube = addCubeMesh(b, "cube", -1);
    const int step = b.add("nodes", {{"name", "step"}, {"mesh", cube}});
    const int spline = b.add("nodes", {{"name", "spline"}, {"mesh", cube}});
    b.addRoot(step);
    b.addRoot(spline);
    nlohmann::json samplers = nlohmann::json::array();
    const std::array<float, 3> stepTimes{0.0f, 1.0f, 2.0f};
    const std::array<float, 9> stepValues{0, 0, 0, 5, 0, 0, 10, 0, 0};
    addSampler(b, samplers, stepTimes, stepValues, "VEC3", "STEP");
    const std::array<float, 2> splineTimes{0.0f, 2.0f};
    // Per key: in-tangent, value, out-tangent.
    const std::array<float, 18> splineValues{0, 0, 0, 0, 0, 0, 1, 0, 0, 3, 0, 0, 4, 0, 0, 0, 0, 0};
    addSampler(b, samplers, splineTimes, splineValues, "VEC3", "CUBICSPLINE");
    b.add("animations", {{"name", "keys"},
                         {"channels",
                          {{{"sampler", 0}, {"target", {{"node", step}, {"path", "translation"}}}},
                           {{"sampler", 1}, {"target", {{"node", spline}, {"path", "translation"}}}}}},
                         {"samplers", samplers}});
    return b;
}

} // namespace penumbra::testing
