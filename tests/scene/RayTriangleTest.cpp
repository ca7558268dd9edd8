#include "penumbra/truth/RayTriangle.hpp"

#include <gtest/gtest.h>

namespace penumbra::truth {
namespace {

const glm::vec3 v0{0, 0, 0}, v1{1, 0, 0}, v2{0, 1, 0}; // counter-clockwise seen from +z

TEST(RayTriangleTest, HitFromTheFrontGivesDistanceAndBarycentrics)
{
    const auto hit = intersectRayTriangle({0.25f, 0.5f, 2.0f}, {0, 0, -1}, v0, v1, v2, 10.0f);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->distance, 2.0f);
    EXPECT_FLOAT_EQ(hit->barycentrics.x, 0.25f); // weight of v1 = x
    EXPECT_FLOAT_EQ(hit->barycentrics.y, 0.5f); // weight of v2 = y
}

TEST(RayTriangleTest, HitFromBehindCounts)
{
    const auto hit = intersectRayTriangle({0.2f, 0.2f, -3.0f}, {0, 0, 1}, v0, v1, v2, 10.0f);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->distance, 3.0f);
}

TEST(RayTriangleTest, ObliqueRayKnownAnswer)
{
    // From (1, 1, 1) towards (0.25, 0.25, 0): direction (-0.75, -0.75, -1), t = 1.
    const auto hit = intersectRayTriangle({1, 1, 1}, {-0.75f, -0.75f, -1.0f}, v0, v1, v2, 10.0f);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->distance, 1.0f, 1e-6f); // in units of |direction|
    EXPECT_NEAR(hit->barycentrics.x, 0.25f, 1e-6f);
    EXPECT_NEAR(hit->barycentrics.y, 0.25f, 1e-6f);
}

TEST(RayTriangleTest, Misses)
{
    EXPECT_FALSE(intersectRayTriangle({0.6f, 0.6f, 1.0f}, {0, 0, -1}, v0, v1, v2, 10.0f)); // outside the hypotenuse
    EXPECT_FALSE(intersectRayTriangle({0.2f, 0.2f, 1.0f}, {0, 0, 1}, v0, v1, v2, 10.0f)); // pointing away
    EXPECT_FALSE(intersectRayTriangle({0.2f, 0.2f, 5.0f}, {0, 0, -1}, v0, v1, v2, 4.0f)); // beyond maxDistance
    EXPECT_FALSE(intersectRayTriangle({-1.0f, 0.2f, 0.0f}, {1, 0, 0}, v0, v1, v2, 10.0f)); // in the plane
    EXPECT_FALSE(intersectRayTriangle({0.2f, 0.2f, 1.0f}, {0, 0, -1}, v0, v1, v1, 10.0f)); // degenerate
    EXPECT_TRUE(intersectRayTriangle({0.2f, 0.2f, 4.0f}, {0, 0, -1}, v0, v1, v2, 4.0f)); // at maxDistance
}

} // namespace
} // namespace penumbra::truth
