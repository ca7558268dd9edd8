// Depth fit on the GPU: the reduction of the frame's depth finds the view depths the camera sees and their
// light-space footprints (with and without MSAA), and cascades fitted to them put at least 1.5 times the stable fit's
// texels per metre on the forest's visible surfaces (median; docs/notes/2026-12-06-depth-fit.md).
#include "GpuTesting.hpp"

#include "penumbra/render/FrameResources.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scenes/TestScenes.hpp"
#include "penumbra/truth/GroundTruth.hpp"
#include "penumbra/truth/RayCaster.hpp"
#include "penumbra/truth/ShadowTruth.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

// Small frames and a small atlas: the forest's leaf cards are slow to draw on the software rasterizers, and the
// reduction and the fit do not depend on the sizes.
constexpr std::uint32_t kDepthFitWidth = 160;
constexpr std::uint32_t kDepthFitHeight = 90;
constexpr std::uint32_t kAtlasSize = 512;

class DepthFitTest : public GpuTest {
protected:
    render::FrameDesc frameOf(shadows::CascadeProjection projection, std::uint32_t msaa = 1) const
    {
        render::FrameDesc frame;
        frame.width = kDepthFitWidth;
        frame.height = kDepthFitHeight;
        frame.msaa = msaa;
        frame.shadows.directional.projection = projection;
        frame.shadows.directional.atlasSize = kAtlasSize;
        return frame;
    }
};

TEST_F(DepthFitTest, ForestReductionHoldsTheVisibleDepthsAndFitsFinerCascades)
{
    const scene::Scene scene = scenes::makeForestScene();
    const truth::RayCaster cameraRays(scene, truth::RayKind::Camera);
    const truth::CpuGBuffer gbuffer =
        truth::traceGBuffer(scene, cameraRays, scene.camera, kDepthFitWidth / 2, kDepthFitHeight / 2);
    float nearest = 1e9f, farthest = 0.0f;
    for (const truth::GBufferSample& sample : gbuffer.samples)
        if (sample.hit()) {
            nearest = std::min(nearest, sample.viewDepth);
            farthest = std::max(farthest, sample.viewDepth);
        }

    render::SceneRenderer renderer(*device, scene);
    renderer.render(scene.camera, frameOf(shadows::CascadeProjection::Stable));
    EXPECT_FALSE(renderer.visibleDepths()) << "only depth-fit frames reduce their depth";
    const shadows::DirectionalShadowPlan stablePlan = renderer.plan();
    const truth::OnScreenTexelDensity stable = truth::directionalTexelsOnScreen(stablePlan, 0, scene.camera, gbuffer);
    const render::FrameDesc depthFit = frameOf(shadows::CascadeProjection::DepthFit);
    // The first depth-fit frame has no histogram yet: the close fit over the usual splits.
    renderer.render(scene.camera, depthFit);
    EXPECT_EQ(renderer.plan().splits.distances,
              (shadows::cascadeSplits(scene.camera.nearPlane, scene.camera.farPlane, depthFit.shadows.maxDistance, 4,
                                      depthFit.shadows.directional.cascadeRatios)
                   .distances));
    ASSERT_TRUE(renderer.visibleDepths());
    const shadows::ViewDepthRange range = *renderer.visibleDepths();
    // The reduced range holds what the ray cast sees (a subset of the pixels) and lies within a grid step of it.
    EXPECT_LE(range.nearDepth, nearest);
    EXPECT_GE(range.farDepth, farthest);
    EXPECT_GT(range.nearDepth, nearest - 2.0f * shadows::depthFitStep(nearest, 8));
    EXPECT_LT(range.farDepth, farthest + 2.0f * shadows::depthFitStep(farthest, 8));
    renderer.render(scene.camera, depthFit);
    const truth::OnScreenTexelDensity fitted =
        truth::directionalTexelsOnScreen(renderer.plan(), 0, scene.camera, gbuffer);
    std::printf("[ depthfit ] %s forest: visible depths %.2f..%.2f m (ray cast %.2f..%.2f), texels per metre on "
                "screen median %.1f -> %.1f (x%.2f), 10th percentile %.1f -> %.1f (x%.2f)\n",
                configuration().c_str(), range.nearDepth, range.farDepth, nearest, farthest, stable.median,
                fitted.median, fitted.median / stable.median, stable.tenthPercentile, fitted.tenthPercentile,
                fitted.tenthPercentile / stable.tenthPercentile);
    EXPECT_GE(fitted.median, 1.5f * stable.median);
    for (std::size_t c = 0; c < 4; ++c)
        EXPECT_LT(renderer.plan().lights.at(0).cascades.at(c).fit.texelSize,
                  stablePlan.lights.at(0).cascades.at(c).fit.texelSize)
            << "cascade " << c;
    EXPECT_EQ(renderer.visibleDepths(), range) << "the same view keeps its range";
}

// With MSAA the forward path's lit depth is multisampled: the depth fit's own single-sampled prepass gives the
// reduction the same pixels.
TEST_F(DepthFitTest, MultisampledFramesReduceTheSameDepths)
{
    const std::array<rhi::Format, 2> targets{render::kLitColorFormat, render::kLitDepthFormat};
    const std::uint32_t samples = lowestMultisampleCount(device->capabilities(), targets);
    if (samples == 0)
        GTEST_SKIP() << "no multisampled lit targets";
    // The single-light scene, not the forest: multisampled leaf cards take seconds a frame on lavapipe.
    const scene::Scene scene = scenes::makeSingleLightScene();
    render::SceneRenderer single(*device, scene), multi(*device, scene);
    single.render(scene.camera, frameOf(shadows::CascadeProjection::DepthFit));
    const render::FrameStats stats = multi.render(scene.camera, frameOf(shadows::CascadeProjection::DepthFit, samples));
    ASSERT_TRUE(single.visibleDepths());
    EXPECT_EQ(multi.visibleDepths(), single.visibleDepths());
    EXPECT_TRUE(std::any_of(stats.passes.begin(), stats.passes.end(), [](const render::PassTiming& pass) {
        return pass.name == render::frame::kSingleSampledDepthPrepass;
    })) << "the single-sampled prepass ran";
}

} // namespace
} // namespace penumbra::testing
