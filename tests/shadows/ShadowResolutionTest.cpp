// The resolution a spot or point light asks for: its own setting scaled by its range's size on screen and its
// intensity, within the limits.
#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/ShadowResolution.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

// Looking down -z from the origin, 60 degrees vertically, 16:9.
ShadowCamera camera()
{
    return {.position = {0, 0, 0},
            .forward = {0, 0, -1},
            .up = {0, 1, 0},
            .fovY = glm::radians(60.0f),
            .aspect = 16.0f / 9.0f,
            .nearPlane = 0.1f,
            .farPlane = 500.0f};
}

TEST(ProjectedSphereHeight, MatchesTheProjectedSilhouetteOnTheAxis)
{
    const ShadowCamera c = camera();
    const glm::mat4 projection = glm::perspective(c.fovY, c.aspect, c.nearPlane, c.farPlane);
    const float distance = 20.0f;
    const float radius = 3.0f;
    // The silhouette's top: the tangent from the camera, at angular radius asin(radius / distance).
    const float angle = std::asin(radius / distance);
    const glm::vec4 top = projection * glm::vec4(0.0f, std::sin(angle), -std::cos(angle), 1.0f);
    // NDC spans 2 over the screen's height; the silhouette spans 2 x top.y / top.w.
    EXPECT_NEAR(projectedSphereHeight(c, {0, 0, -distance}, radius), top.y / top.w, 1e-5f);
}

TEST(ProjectedSphereHeight, ZeroOutsideTheFrustumOneAroundTheCamera)
{
    const ShadowCamera c = camera();
    EXPECT_EQ(projectedSphereHeight(c, {0, 0, 20}, 5.0f), 0.0f); // behind
    EXPECT_EQ(projectedSphereHeight(c, {0, 50, -20}, 5.0f), 0.0f); // above the top plane
    EXPECT_EQ(projectedSphereHeight(c, {-60, 0, -20}, 5.0f), 0.0f); // left of the left plane
    EXPECT_EQ(projectedSphereHeight(c, {0, 0, -600}, 5.0f), 0.0f); // beyond the far plane
    EXPECT_GT(projectedSphereHeight(c, {0, 15, -20}, 5.0f), 0.0f); // straddles the top plane
    EXPECT_GT(projectedSphereHeight(c, {0, 0, 3}, 5.0f), 0.0f); // behind, but reaches past the near plane
    EXPECT_EQ(projectedSphereHeight(c, {1, 1, 1}, 5.0f), 1.0f); // holds the camera
}

TEST(LocalShadowRequest, CloserLightsAskForLargerTiles)
{
    const ShadowCamera c = camera();
    float previousSize = 1e9f;
    float previousPriority = 1e9f;
    bool someLarger = false;
    for (float distance = 5.0f; distance < 400.0f; distance *= 1.3f) {
        const ShadowResolutionRequest r = localShadowRequest(c, {.position = {2, -1, -distance}, .range = 6.0f});
        EXPECT_LE(r.size, previousSize) << distance;
        EXPECT_LE(r.priority, previousPriority) << distance;
        someLarger = someLarger || r.size < previousSize;
        previousSize = r.size;
        previousPriority = r.priority;
    }
    EXPECT_TRUE(someLarger);
    const ShadowResolutionLimits limits;
    EXPECT_EQ(localShadowRequest(c, {.position = {0, 0, -7}, .range = 6.0f}).size, limits.defaultSize);
    EXPECT_EQ(localShadowRequest(c, {.position = {0, 0, -390}, .range = 6.0f}).size, limits.floorSize);
}

TEST(LocalShadowRequest, OffScreenDimOrTinyLightsAskForTheFloor)
{
    const ShadowCamera c = camera();
    const ShadowResolutionLimits limits{.floorSize = 32.0f, .maxSize = 2048.0f, .defaultSize = 1024.0f};
    const ShadowResolutionRequest behind = localShadowRequest(c, {.position = {0, 0, 30}, .range = 6.0f}, limits);
    EXPECT_EQ(behind.size, 32.0f);
    EXPECT_EQ(behind.priority, 0.0f);
    EXPECT_EQ(localShadowRequest(c, {.position = {0, 0, -10}, .range = 6.0f, .relativeIntensity = 0.0f}, limits).size,
              32.0f);
    EXPECT_EQ(localShadowRequest(c, {.position = {0, 0, -100}, .range = 0.1f}, limits).size, 32.0f);
}

TEST(LocalShadowRequest, GrowsWithIntensityRangeAndItsOwnResolutionWithinTheLimits)
{
    const ShadowCamera c = camera();
    const LocalLightImportance base{.position = {0, 0, -20}, .range = 5.0f, .relativeIntensity = 0.25f};
    const float size = localShadowRequest(c, base).size;
    LocalLightImportance brighter = base;
    brighter.relativeIntensity = 1.0f;
    EXPECT_NEAR(localShadowRequest(c, brighter).size, 2.0f * size, 1e-3f); // square root of 4
    LocalLightImportance wider = base;
    wider.range = 8.0f;
    EXPECT_GT(localShadowRequest(c, wider).size, size);
    LocalLightImportance own = base;
    own.shadowResolution = 4096.0f;
    EXPECT_NEAR(localShadowRequest(c, own).size, 8.0f * size, 1e-2f);
    own.position = {0, 0, -6};
    EXPECT_EQ(localShadowRequest(c, own).size, ShadowResolutionLimits{}.maxSize);
}

TEST(LocalShadowRequest, RejectsBadLimitsAndLights)
{
    const ShadowCamera c = camera();
    EXPECT_THROW(localShadowRequest(c, {}, {.floorSize = 0.0f}), rhi::Error);
    EXPECT_THROW(localShadowRequest(c, {}, {.floorSize = 512.0f, .maxSize = 256.0f}), rhi::Error);
    EXPECT_THROW(localShadowRequest(c, {.range = 0.0f}), rhi::Error);
    EXPECT_THROW(localShadowRequest(c, {.shadowResolution = -1.0f}), rhi::Error);
}

} // namespace
} // namespace penumbra::shadows
