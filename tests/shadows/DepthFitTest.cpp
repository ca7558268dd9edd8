// Depth fit: the stable fit over splits of the visible view depths, quantized with hysteresis.
#include "penumbra/shadows/DepthFit.hpp"
#include "penumbra/shadows/DirectionalShadowPlanner.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace penumbra::shadows {
namespace {

const rhi::Conventions conventions{rhi::DepthRange::ZeroToOne, true};

TEST(DepthFit, RangeIsOnTheGridAndHoldsTheMeasuredOne)
{
    // 8 steps per octave: 0.125 m steps in [1, 2), 4 m steps in [32, 64).
    EXPECT_EQ(depthFitStep(1.5f, 8), 0.125f);
    EXPECT_EQ(depthFitStep(40.0f, 8), 4.0f);
    const ViewDepthRange fitted = quantizeViewDepthRange({1.3f, 37.0f}, std::nullopt, 8, 1.0f);
    EXPECT_EQ(fitted, (ViewDepthRange{1.25f, 40.0f}));
    // An end on the grid stays where it is.
    EXPECT_EQ(quantizeViewDepthRange({2.0f, 32.0f}, std::nullopt, 8, 1.0f), (ViewDepthRange{2.0f, 32.0f}));
    // Unquantized: as measured.
    EXPECT_EQ(quantizeViewDepthRange({1.3f, 37.0f}, std::nullopt, 0, 1.0f), (ViewDepthRange{1.3f, 37.0f}));
}

TEST(DepthFit, HysteresisKeepsTheRangeUntilTheDepthsMoveMoreThanItsSteps)
{
    const ViewDepthRange kept{1.25f, 40.0f};
    // Depths that cross a grid line inwards keep the range (quantized alone, far would fall to 36, near rise to 1.375).
    EXPECT_EQ(quantizeViewDepthRange({1.38f, 35.0f}, kept, 8, 1.0f), kept);
    EXPECT_EQ(quantizeViewDepthRange({1.38f, 35.0f}, kept, 8, 0.0f), (ViewDepthRange{1.375f, 36.0f}));
    // Beyond 1 + hysteresis steps inside (40 - 2 x 4 = 32), the range narrows.
    EXPECT_EQ(quantizeViewDepthRange({1.3f, 31.0f}, kept, 8, 1.0f).farDepth, 32.0f);
    EXPECT_EQ(quantizeViewDepthRange({1.55f, 38.0f}, kept, 8, 1.0f).nearDepth, 1.5f);
    // Depths outside the kept range widen it at once: the fit must hold what is seen.
    EXPECT_EQ(quantizeViewDepthRange({1.2f, 41.0f}, kept, 8, 4.0f), (ViewDepthRange{1.125f, 44.0f}));
}

TEST(DepthFit, SmallDepthChangesKeepTheSplits)
{
    const glm::vec3 ratios{0.1f, 0.25f, 0.5f};
    std::optional<ViewDepthRange> kept;
    std::optional<CascadeSplits> first;
    // A visible far depth that wanders by +-1 m about 37 m (the camera stepping back and forth) keeps every split.
    for (int frame = 0; frame < 40; ++frame) {
        const float wander = (frame % 2 ? 1.0f : -1.0f) * 0.05f * static_cast<float>(frame % 20);
        kept = quantizeViewDepthRange({1.3f, 37.0f + wander}, kept, 8, 1.0f);
        const CascadeSplits splits = depthFitSplits(*kept, 0.1f, 150.0f, 100.0f, 4, ratios, 8);
        if (!first)
            first = splits;
        EXPECT_EQ(splits.distances, first->distances) << "frame " << frame;
    }
    // The inner splits lie on the grid and in order, the outer ones at the range's ends.
    EXPECT_EQ(first->nearOf(0), 1.25f);
    EXPECT_EQ(first->farOf(3), 40.0f);
    for (std::uint32_t i = 1; i < 4; ++i) {
        const float split = first->distances[i];
        EXPECT_GT(split, first->distances[i - 1]);
        EXPECT_EQ(std::fmod(split, depthFitStep(split, 8)), 0.0f) << split;
    }
}

TEST(DepthFit, SplitsStayWithinTheCameraAndTheShadowDistance)
{
    const CascadeSplits splits = depthFitSplits({0.01f, 500.0f}, 0.1f, 150.0f, 100.0f, 4, {0.1f, 0.25f, 0.5f}, 8);
    EXPECT_EQ(splits.nearOf(0), 0.1f);
    EXPECT_EQ(splits.farOf(3), 100.0f);
}

// The planner: depth fit without a range is the stable fit; with a shorter visible range its tiles are finer.
TEST(DepthFit, PlannerFitsTheCascadesToTheVisibleDepths)
{
    ShadowCamera camera;
    camera.position = {0.0f, 2.0f, 0.0f};
    camera.forward = glm::normalize(glm::vec3(0.0f, -0.2f, 1.0f));
    camera.up = glm::normalize(glm::cross(glm::cross(camera.forward, glm::vec3(0, 1, 0)), camera.forward));
    camera.aspect = 16.0f / 9.0f;
    camera.farPlane = 150.0f;
    ShadowSettings settings;
    const std::vector<DirectionalShadowLightInput> lights{{glm::normalize(glm::vec3(-0.4f, -1.0f, 0.5f))}};
    const std::vector<Bounds> casters{{glm::vec3(-1.0f), glm::vec3(1.0f)}};
    const DirectionalShadowPlan stable = planDirectionalShadows(settings, conventions, camera, lights, casters);
    settings.directional.projection = CascadeProjection::DepthFit;
    const DirectionalShadowPlan fallback = planDirectionalShadows(settings, conventions, camera, lights, casters);
    const DirectionalShadowPlan fitted =
        planDirectionalShadows(settings, conventions, camera, lights, casters, ViewDepthRange{1.25f, 40.0f});
    ASSERT_EQ(fitted.lights.size(), 1u);
    EXPECT_EQ(fitted.uniforms.cascadeProjection, CascadeProjection::DepthFit);
    for (std::uint32_t c = 0; c < 4; ++c) {
        const float stableTexel = stable.lights[0].cascades[c].fit.texelSize;
        EXPECT_EQ(fallback.lights[0].cascades[c].fit.texelSize, stableTexel);
        // 40 m instead of 100 m: the first cascade (10 m to 5 m deep, but as wide at its far end) 1.5 times as fine,
        // the others twice.
        EXPECT_LT(fitted.lights[0].cascades[c].fit.texelSize, (c == 0 ? 0.67f : 0.5f) * stableTexel) << "cascade " << c;
    }
}

} // namespace
} // namespace penumbra::shadows
