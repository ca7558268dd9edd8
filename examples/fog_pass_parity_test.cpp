// The fog pass (FogPass.hpp), an application's pass in the frame graph, renders the same on every configuration: the
// fog reads the lit depth back to view space through each configuration's own conventions.
#include "FogPass.hpp"

#include <penumbra/parity/GoogleTest.hpp>
#include <penumbra/scenes/TestScenes.hpp>

#include <gtest/gtest.h>

using namespace penumbra;

std::vector<parity::Picture> renderFog(rhi::Device& device, const rhi::NamedConfiguration&)
{
    // At 192 x 108 the test scene's lit picture itself differs along one row between opengl (clip control) and the
    // other configurations (an edge through pixel centres, a rasterization tie); at 160 x 90 it does not.
    constexpr std::uint32_t width = 160, height = 90;
    examples::FoggedScene fogged(device, scenes::makeShadowTestScene(), width, height);
    fogged.renderer->render(fogged.scene.camera, render::FrameDesc{.width = width, .height = height});
    return {parity::colorPicture("fogged", rhi::readTexture(device, *fogged.fogged))};
}

TEST(FogPass, SameOnEveryConfiguration)
{
    parity::Options options;
    // The depths' rounding differs between depth ranges and directions: a channel may differ by a step or two.
    options.thresholds["fogged"] = {.maxDifference = 2.0};
    PENUMBRA_EXPECT_PARITY(renderFog, options);
}
