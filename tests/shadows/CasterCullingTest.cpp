#include "penumbra/shadows/CasterBvh.hpp"
#include "penumbra/shadows/CasterCulling.hpp"
#include "penumbra/shadows/LocalShadowPlanner.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <random>

#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

Bounds cube(glm::vec3 centre, float half) { return {centre - half, centre + half}; }

// Camera at the origin looking down -z; light straight down (light depth is -y); cascades [0.1, 10], [10, 50].
class CasterCullingTest : public ::testing::Test {
protected:
    ShadowCamera camera{};
    rhi::Conventions conventions{rhi::DepthRange::ZeroToOne, false};
    CascadeSplits splits = cascadeSplits(0.1f, 100.0f, 50.0f, 2, {0.2f, 0.5f, 0.9f});
    std::vector<DirectionalShadowCascade> cascades;
    std::vector<Bounds> casters;

    void SetUp() override
    {
        const std::vector<DirectionalShadowCascade> empty = fit({});
        const Sphere first = empty[0].cullingSphere;
        casters = {
            cube(first.centre + glm::vec3(0, 0, -0.45f * first.radius), 0.5f), // A: deep in cascade 0's sphere
            cube({500.0f, 0.0f, -20.0f}, 1.0f), // B: outside every footprint
            {{-1.0f, 80.0f, -31.0f}, {1.0f, 90.0f, -29.0f}}, // C: high above cascade 1 only
            {{-1.0f, -200.0f, -11.0f}, {1.0f, -190.0f, -9.0f}}, // D: below both far planes
            cube(first.centre + glm::vec3(0, 0, -0.75f * first.radius), 0.5f), // E: across the 0.7 r boundary
        };
        cascades = fit(casters);
    }

    std::vector<DirectionalShadowCascade> fit(std::span<const Bounds> bounds) const
    {
        return computeDirectionalShadowMatricesAndCullingPrimitives(camera, splits, 0, 2, {0.0f, -1.0f, 0.0f}, 512,
                                                                    0.0f, bounds, conventions);
    }
};

TEST_F(CasterCullingTest, CastersInTheCascadeBoxIncludingAnyDistanceTowardTheLight)
{
    const CasterCullingResult first =
        cullShadowCasters(cascades[0], lightSpaceCasters(cascades[0].basis, casters), std::nullopt, 0.7f);
    EXPECT_EQ(first.casters, (std::vector<std::uint32_t>{0, 4}));
    EXPECT_EQ(first.overlapping, 2u);
    EXPECT_EQ(first.culledByBias, 0u);

    const CasterCullingResult unbiased =
        cullShadowCasters(cascades[1], lightSpaceCasters(cascades[1].basis, casters), cascades[0].cullingSphere, 0.0f);
    EXPECT_EQ(unbiased.casters, (std::vector<std::uint32_t>{0, 2, 4}));
    EXPECT_EQ(unbiased.overlapping, 3u);
    EXPECT_EQ(unbiased.culledByBias, 0u);
}

TEST_F(CasterCullingTest, CullingBiasSkipsCastersWhollyInsideThePreviousSphere)
{
    const float factor = cascadeBlendCullingFactor(0.1f);
    EXPECT_FLOAT_EQ(factor, 0.7f);
    EXPECT_EQ(cascadeBlendCullingFactor(0.9f), 0.0f);
    const CasterCullingResult biased = cullShadowCasters(cascades[1], lightSpaceCasters(cascades[1].basis, casters),
                                                         cascades[0].cullingSphere, factor);
    EXPECT_EQ(biased.casters, (std::vector<std::uint32_t>{2, 4}));
    EXPECT_EQ(biased.overlapping, 3u);
    EXPECT_EQ(biased.culledByBias, 1u);
    // Draws with and without the culling bias, over both cascades.
    const CasterCullingResult first =
        cullShadowCasters(cascades[0], lightSpaceCasters(cascades[0].basis, casters), std::nullopt, factor);
    EXPECT_EQ(first.casters.size() + biased.casters.size(), 4u);
    EXPECT_EQ(first.overlapping + biased.overlapping, 5u);
}

// casterInVolume, the reference the GPU culling pass mirrors, gives each cascade the planner's list, with the culling
// bias of a sphere and of a frustum slice, and each frustum the local planner's.
TEST_F(CasterCullingTest, VolumesGiveThePlannersLists)
{
    const LightSpaceCasters light = lightSpaceCasters(cascades[1].basis, casters);
    const auto listed = [&](const CasterVolume& volume) {
        std::vector<std::uint32_t> inside;
        for (std::uint32_t i = 0; i < casters.size(); ++i)
            if (casterInVolume(casters[i], volume))
                inside.push_back(i);
        return inside;
    };
    const float factor = cascadeBlendCullingFactor(0.1f);
    const Sphere previous = cascades[0].cullingSphere;
    EXPECT_EQ(listed(cascadeVolume(cascades[1], previous, factor)),
              cullShadowCasters(cascades[1], light, previous, factor).casters);
    EXPECT_EQ(listed(cascadeVolume(cascades[0], std::nullopt, factor)),
              cullShadowCasters(cascades[0], light, std::nullopt, factor).casters);
    const FrustumSlice slice{camera, splits.nearOf(0), splits.farOf(0)};
    EXPECT_EQ(listed(closeCascadeVolume(cascades[1], slice, factor)),
              cullCloseFitShadowCasters(cascades[1], light, slice, factor).casters);
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 20.0f, -5.0f), glm::vec3(0.0f, 0.0f, -5.0f), {0, 0, -1});
    const std::vector<std::uint32_t> frustum = cullCastersInFrustum(view, 1.2f, 0.5f, 40.0f, casters);
    EXPECT_EQ(listed(frustumVolume(view, 1.2f, 0.5f, 40.0f)), frustum);
    EXPECT_FALSE(frustum.empty());
    EXPECT_LT(frustum.size(), casters.size());
}

// A camera's frustum is as wide as its aspect makes it and as high as its vertical field of view: a box just right of
// the square frustum is in the view of a wide camera, one just above it in neither.
TEST(CasterVolumeTest, CameraFrustumIsWiderThanHigh)
{
    const glm::mat4 view(1.0f); // the eye at the origin, looking down -z
    const float fovY = 1.0f, tanY = std::tan(0.5f * fovY);
    const Bounds right{{1.1f * tanY * 10.0f, -0.1f, -10.1f}, {1.2f * tanY * 10.0f, 0.1f, -9.9f}};
    const Bounds above{{-0.1f, 1.1f * tanY * 10.0f, -10.1f}, {0.1f, 1.2f * tanY * 10.0f, -9.9f}};
    const CasterVolume square = frustumVolume(view, fovY, 0.1f, 100.0f);
    const CasterVolume wide = frustumVolume(view, fovY, 16.0f / 9.0f, 0.1f, 100.0f);
    EXPECT_FALSE(casterInVolume(right, square));
    EXPECT_TRUE(casterInVolume(right, wide));
    EXPECT_FALSE(casterInVolume(above, square));
    EXPECT_FALSE(casterInVolume(above, wide));
    const std::vector<Bounds> boxes{right, above};
    EXPECT_EQ(CasterBvh(boxes).inFrustum(wide), std::vector<std::uint32_t>{0});
}

// The hierarchy gives each frustum and range the brute-force answer, box for box: 600 boxes of mixed sizes (some
// straddling many views), 200 views from random places in random directions.
TEST(CasterBvhTest, ListsAreTheBruteForceOnes)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<float> place(-200.0f, 200.0f), unit(-1.0f, 1.0f), size(0.05f, 1.0f);
    std::vector<Bounds> boxes;
    for (int i = 0; i < 600; ++i) {
        const glm::vec3 centre(place(random), 0.1f * place(random), place(random));
        const float half = i % 50 == 0 ? 80.0f * size(random) : 4.0f * size(random);
        boxes.push_back({centre - half * glm::vec3(size(random), size(random), size(random)),
                         centre + half * glm::vec3(size(random), size(random), size(random))});
    }
    const CasterBvh bvh(boxes);
    std::size_t listed = 0;
    for (int v = 0; v < 200; ++v) {
        const glm::vec3 eye(place(random), 0.1f * place(random), place(random));
        glm::vec3 direction(unit(random), unit(random), unit(random));
        direction = glm::length(direction) > 1e-3f ? glm::normalize(direction) : glm::vec3(0.0f, -1.0f, 0.0f);
        const glm::vec3 up = std::abs(direction.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        const glm::mat4 view = glm::lookAt(eye, eye + direction, up);
        const float fov = 0.2f + 2.8f * size(random), nearPlane = 0.05f * size(random), range = 100.0f * size(random);
        const std::vector<std::uint32_t> expected = cullCastersInFrustum(view, fov, nearPlane, range, boxes);
        const CasterVolume volume = frustumVolume(view, fov, nearPlane, range);
        EXPECT_EQ(bvh.inFrustum(volume), expected) << "view " << v;
        EXPECT_EQ(bvh.anyInFrustum(volume), !expected.empty()) << "view " << v;
        // A camera's view, wider or narrower than high, against casterInVolume box by box.
        const CasterVolume camera = frustumVolume(view, fov, 0.5f + 1.5f * size(random), nearPlane, range);
        std::vector<std::uint32_t> inCamera;
        for (std::uint32_t i = 0; i < boxes.size(); ++i)
            if (casterInVolume(boxes[i], camera))
                inCamera.push_back(i);
        EXPECT_EQ(bvh.inFrustum(camera), inCamera) << "view " << v;
        listed += expected.size();
        const bool inRange = std::any_of(boxes.begin(), boxes.end(), [&](const Bounds& b) {
            const glm::vec3 nearest = glm::clamp(eye, b.min, b.max);
            return glm::dot(nearest - eye, nearest - eye) <= range * range;
        });
        EXPECT_EQ(bvh.anyInRange(eye, range), inRange) << "view " << v;
    }
    EXPECT_GT(listed, 200u); // the views see something
    EXPECT_LT(listed, 200u * boxes.size() / 4); // and far from everything
    EXPECT_TRUE(
        CasterBvh(std::span<const Bounds>()).inFrustum(frustumVolume(glm::mat4(1.0f), 1.0f, 0.1f, 10.0f)).empty());
}

} // namespace
} // namespace penumbra::shadows
