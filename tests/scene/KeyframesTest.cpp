// Keyframe sampling and skinning math against values computed by hand from glTF 2.0 Appendix C and section 3.7.3.
#include "penumbra/scene/Keyframes.hpp"
#include "penumbra/scene/Posing.hpp"
#include "penumbra/scene/Skinning.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace penumbra::scene {
namespace {

Keyframes scalarKeys(std::vector<float> times, std::vector<float> values, Interpolation interpolation)
{
    return {std::move(times), std::move(values), 1, interpolation};
}

TEST(KeyframesTest, LinearInterpolatesAndClampsAtBothEnds)
{
    const Keyframes keys = scalarKeys({1.0f, 3.0f}, {10.0f, 20.0f}, Interpolation::Linear);
    EXPECT_FLOAT_EQ(sampleKeyframes(keys, 0.0f)[0], 10.0f);
    EXPECT_FLOAT_EQ(sampleKeyframes(keys, 2.5f)[0], 17.5f);
    EXPECT_FLOAT_EQ(sampleKeyframes(keys, 9.0f)[0], 20.0f);
}

TEST(KeyframesTest, StepHoldsTheKeyAtOrBefore)
{
    const Keyframes keys = scalarKeys({0.0f, 1.0f, 2.0f}, {0.0f, 5.0f, 10.0f}, Interpolation::Step);
    EXPECT_FLOAT_EQ(sampleKeyframes(keys, 0.999f)[0], 0.0f);
    EXPECT_FLOAT_EQ(sampleKeyframes(keys, 1.0f)[0], 5.0f);
    EXPECT_FLOAT_EQ(sampleKeyframes(keys, 1.5f)[0], 5.0f);
    EXPECT_FLOAT_EQ(sampleKeyframes(keys, 2.5f)[0], 10.0f);
}

// Appendix C at t = 1 of keys at 0 and 2 (interval 2, u = 0.5): h00 = 0.5, h10 = 0.125, h01 = 0.5, h11 = -0.125,
// p = 0.5 * 0 + 2 * 0.125 * 1 + 0.5 * 4 + 2 * (-0.125) * 3 = 1.5. The tangents are scaled by the interval: without
// it the value would be 0.125 - 0.375 + 2 = 1.75.
TEST(KeyframesTest, CubicSplineIsHermiteWithTangentsTimesTheInterval)
{
    const Keyframes keys = scalarKeys({0.0f, 2.0f}, {0.0f, 0.0f, 1.0f, 3.0f, 4.0f, 0.0f}, Interpolation::CubicSpline);
    EXPECT_FLOAT_EQ(sampleKeyframes(keys, 1.0f)[0], 1.5f);
    EXPECT_FLOAT_EQ(sampleKeyframes(keys, 0.0f)[0], 0.0f);
    EXPECT_FLOAT_EQ(sampleKeyframes(keys, 2.0f)[0], 4.0f);
    EXPECT_FLOAT_EQ(sampleKeyframes(keys, 5.0f)[0], 4.0f);
}

TEST(KeyframesTest, RotationsSlerpAlongTheShorterArc)
{
    const float h = std::sqrt(0.5f);
    // 0 and 90 degrees about z; the second stored negated (the same rotation) must still take the short way.
    const Keyframes keys{{0.0f, 1.0f}, {0, 0, 0, 1, 0, 0, -h, -h}, 4, Interpolation::Linear};
    const glm::quat half = sampleRotation(keys, 0.5f);
    const glm::vec3 x = half * glm::vec3(1.0f, 0.0f, 0.0f);
    EXPECT_NEAR(x.x, h, 1e-6f);
    EXPECT_NEAR(x.y, h, 1e-6f);
    // A third of the way: 30 degrees, which a normalized lerp misses (it gives 29.3).
    const glm::vec3 third = sampleRotation(keys, 1.0f / 3.0f) * glm::vec3(1.0f, 0.0f, 0.0f);
    EXPECT_NEAR(std::atan2(third.y, third.x), glm::radians(30.0f), 1e-5f);
}

TEST(KeyframesTest, SkinningBlendsJointMatricesAndTurnsNormals)
{
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    const std::vector<glm::mat4> joints{glm::mat4(1.0f), turn};
    const std::vector<glm::uvec4> indices{glm::uvec4(0, 1, 0, 0)};
    const std::vector<glm::vec4> weights{glm::vec4(0.25f, 0.75f, 0.0f, 0.0f)};
    Vertex vertex;
    vertex.position = glm::vec3(2.0f, 0.0f, 0.0f);
    vertex.normal = glm::vec3(1.0f, 0.0f, 0.0f);
    const Vertex skinned = skinVertex(vertex, skinMatrix(indices, weights, joints));
    // 0.25 * (2, 0, 0) + 0.75 * (0, 2, 0).
    EXPECT_NEAR(skinned.position.x, 0.5f, 1e-6f);
    EXPECT_NEAR(skinned.position.y, 1.5f, 1e-6f);
    EXPECT_NEAR(glm::length(skinned.normal), 1.0f, 1e-6f);
    EXPECT_GT(skinned.normal.y, skinned.normal.x);
}

// Section 3.7.2.2: each target adds its offsets times its weight to position, normal and tangent xyz; w stays.
TEST(KeyframesTest, MorphTargetsAddWeightedOffsetsToEveryAttribute)
{
    Vertex rest;
    rest.tangent = glm::vec4(1.0f, 0.0f, 0.0f, -1.0f);
    const std::vector<MorphTarget> targets{
        {{glm::vec3(0.0f, 2.0f, 0.0f)}, {glm::vec3(1.0f, 0.0f, 0.0f)}, {}},
        {{}, {}, {glm::vec3(0.0f, 0.0f, 4.0f)}},
    };
    const std::vector<float> weights{0.5f, 0.25f};
    const Vertex morphed = morphVertex(rest, targets, weights, 0);
    EXPECT_EQ(morphed.position, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(morphed.normal, glm::vec3(0.5f, 1.0f, 0.0f));
    EXPECT_EQ(morphed.tangent, glm::vec4(1.0f, 0.0f, 1.0f, -1.0f));
}

TEST(KeyframesTest, WorldTransformsComposeParentsFirst)
{
    Rig rig;
    rig.nodes.push_back({.name = "root", .parent = -1, .translation = glm::vec3(1.0f, 0.0f, 0.0f)});
    rig.nodes.push_back({.name = "child", .parent = 0, .translation = glm::vec3(0.0f, 2.0f, 0.0f)});
    rig.animations.push_back(
        {"move", {{{0.0f, 1.0f}, {0, 0, 0, 0, 0, 4}, 3, Interpolation::Linear}}, {{1, AnimatedPath::Translation, 0}}});
    NodePose pose = restPose(rig);
    applyAnimation(rig.animations[0], 0.5f, pose);
    const std::vector<glm::mat4> world = worldTransforms(rig, pose);
    EXPECT_EQ(glm::vec3(world[1][3]), glm::vec3(1.0f, 0.0f, 2.0f));
}

} // namespace
} // namespace penumbra::scene
