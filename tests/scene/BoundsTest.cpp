#include "penumbra/scene/Geometry.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace penumbra::scene {
namespace {

TEST(BoundsTest, DefaultIsEmptyAndExtendGivesThePointsBox)
{
    Bounds bounds;
    EXPECT_TRUE(bounds.empty());
    bounds.extend(glm::vec3(1.0f, -2.0f, 3.0f));
    bounds.extend(glm::vec3(-1.0f, 2.0f, 0.0f));
    EXPECT_FALSE(bounds.empty());
    EXPECT_EQ(bounds.min, glm::vec3(-1.0f, -2.0f, 0.0f));
    EXPECT_EQ(bounds.max, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(bounds.center(), glm::vec3(0.0f, 0.0f, 1.5f));
}

TEST(BoundsTest, CornersFollowTheBitOrder)
{
    const Bounds bounds{{0, 0, 0}, {1, 2, 3}};
    const auto corners = bounds.corners();
    EXPECT_EQ(corners[0], glm::vec3(0, 0, 0));
    EXPECT_EQ(corners[1], glm::vec3(1, 0, 0));
    EXPECT_EQ(corners[2], glm::vec3(0, 2, 0));
    EXPECT_EQ(corners[4], glm::vec3(0, 0, 3));
    EXPECT_EQ(corners[7], glm::vec3(1, 2, 3));
}

TEST(BoundsTest, MergeCoversBoth)
{
    const Bounds a{{0, 0, 0}, {1, 1, 1}};
    const Bounds b{{-2, 0.5f, 0.5f}, {0.5f, 3, 0.5f}};
    const Bounds merged = a.merged(b);
    EXPECT_EQ(merged.min, glm::vec3(-2, 0, 0));
    EXPECT_EQ(merged.max, glm::vec3(1, 3, 1));
    EXPECT_EQ(Bounds{}.merged(a).min, a.min); // the empty box is merge's identity
}

TEST(BoundsTest, TransformedIsTheBoxOfTheTransformedCorners)
{
    const Bounds unit{{-1, -1, -1}, {1, 1, 1}};
    // 45 degrees about y: the x and z extents grow to sqrt(2).
    const glm::mat4 m =
        glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0)), glm::radians(45.0f), glm::vec3(0, 1, 0));
    const Bounds world = unit.transformed(m);
    EXPECT_NEAR(world.min.x, 10.0f - std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(world.max.x, 10.0f + std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(world.min.y, -1.0f, 1e-6f);
    EXPECT_NEAR(world.max.z, std::sqrt(2.0f), 1e-5f);
    for (const glm::vec3& corner : unit.corners())
        EXPECT_TRUE(world.contains(glm::vec3(m * glm::vec4(corner, 1.0f)), 1e-5f));
    EXPECT_TRUE(Bounds{}.transformed(m).empty());
}

} // namespace
} // namespace penumbra::scene
