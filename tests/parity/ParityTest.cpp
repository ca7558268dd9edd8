#include "GpuTesting.hpp"
#include "PrecisionScene.hpp"
#include "TestPattern.hpp"

#include "penumbra/parity/GoogleTest.hpp"
#include "penumbra/rhi/Error.hpp"

#include <cmath>
#include <fmt/format.h>
#include <iostream>

namespace penumbra::testing {
namespace {

// The test pattern, 128 x 128: its colours and its depth in linear view depth.
std::vector<parity::Picture> renderPattern(rhi::Device& device, const rhi::NamedConfiguration&)
{
    pattern::PatternRenderer renderer(device, {.width = 128, .height = 128});
    renderer.render(pattern::testPattern());
    return {parity::colorPicture("pattern", renderer.color()),
            parity::viewDepthPicture("depth", renderer.depth(), renderer.projection())};
}

// The pattern through every configuration this build has, with validation on, once for the tests below.
const std::vector<parity::ConfigurationRun>& patternRuns()
{
    static const std::vector<parity::ConfigurationRun> runs = parity::renderConfigurations(renderPattern);
    return runs;
}

// Colours byte-identical; view depth (2 to 9 units) within 2e-4 units (measured 6.3e-5), coverage exact, and raw depth
// bit-identical where the conventions agree.
const parity::Options& patternThresholds()
{
    static const parity::Options options{
        .thresholds = {{"pattern", parity::identical()}, {"depth", {.maxDifference = 2e-4}}}};
    return options;
}

TEST(ParityTest, EveryConfigurationIsRendered)
{
    std::vector<std::string> rendered;
    std::string reasons;
    for (const parity::ConfigurationRun& run : patternRuns()) {
        if (run.status == parity::ConfigurationRun::Status::Rendered)
            rendered.push_back(run.name());
        else
            reasons += fmt::format("\n  {}: {}", run.name(), run.message);
    }
    EXPECT_EQ(rendered, compiledConfigurations()) << "configurations this build has that did not render:" << reasons;
}

TEST(ParityTest, PatternIsByteIdenticalAndViewDepthAgreesEverywhere)
{
    PENUMBRA_EXPECT_PARITY(patternRuns(), patternThresholds());
}

// The negative controls of the test above, judged by the same thresholds on a real rendered pattern: one
// pixel changed by one level in one channel, the smallest fault there is; one texel of depth 0.1 % farther
// (5e-3 units at the centre's depth of 5).
TEST(ParityTest, ChangedPatternPixelCatchesFault)
{
    const parity::ConfigurationRun& first = patternRuns().front();
    ASSERT_EQ(first.status, parity::ConfigurationRun::Status::Rendered) << first.message;
    const rhi::Conventions conventions = first.conventions();
    const parity::Picture& pattern = first.picture("pattern");
    parity::Picture changed = pattern;
    std::byte& green =
        changed.color.bytes[(std::size_t(changed.width()) * (changed.height() / 2) + changed.width() / 2) * 4 + 1];
    green = std::byte(std::uint8_t(green) ^ 1u);
    const parity::Thresholds& exact = patternThresholds().thresholds.at("pattern");
    ASSERT_TRUE(parity::comparePictures(pattern, conventions, pattern, conventions, exact).pass());
    EXPECT_FALSE(parity::comparePictures(pattern, conventions, changed, conventions, exact).pass());
}

TEST(ParityTest, ChangedDepthTexelCatchesFault)
{
    const parity::ConfigurationRun& first = patternRuns().front();
    ASSERT_EQ(first.status, parity::ConfigurationRun::Status::Rendered) << first.message;
    const rhi::Conventions conventions = first.conventions();
    const parity::Picture& depth = first.picture("depth");
    const std::size_t centre = std::size_t(depth.width()) * (depth.height() / 2) + depth.width() / 2;
    ASSERT_NE(depth.depth.depth[centre], conventions.farDepth()) << "the pattern covers the centre";
    parity::Picture farther = depth;
    const float view = conventions.viewDepth(depth.projection, depth.depth.depth[centre]);
    farther.depth.depth[centre] = conventions.windowDepth(depth.projection, view * 1.001f);
    const parity::Thresholds& bound = patternThresholds().thresholds.at("depth");
    ASSERT_TRUE(parity::comparePictures(depth, conventions, depth, conventions, bound).pass());
    const parity::PictureComparison same = parity::comparePictures(depth, conventions, farther, conventions, bound);
    EXPECT_EQ(same.figures.rawDifferingTexels, 1u);
    EXPECT_FALSE(same.pass());
    // The view-depth bound catches it on its own, as it must across conventions, where raw depth is not compared.
    parity::Thresholds viewDepthOnly = bound;
    viewDepthOnly.bitExactWhereConventionsAgree = false;
    const parity::PictureComparison across =
        parity::comparePictures(depth, conventions, farther, conventions, viewDepthOnly);
    EXPECT_GT(across.figures.maxDifference, bound.maxDifference);
    EXPECT_FALSE(across.pass());
}

// Two triangles of one depth, red above green, whose shared horizontal edge runs through the centres of row 7 of 16
// (NDC y = 1 - 7.5 / 8). Which triangle a centre on an edge belongs to is the rasterizer's tie rule, which no API
// fixes in the canonical convention's terms. Vulkan's top-left rule (Vulkan 1.3 section 28.7.1, "Polygon
// Rasterization") gives the row to the green triangle, whose top edge it is; so does GL with the vertex-stage flip
// (opengl-noclip). Under glClipControl(GL_UPPER_LEFT) (opengl, opengl-reversed) Mesa turns the rule over
// (st_atom_rasterizer.c, bottom_edge_rule) and the row is red: the one pixel in which `penumbra render --scene test
// --size 320x180` differs between vulkan and opengl. Known, not yet fixed: flipping in the vertex stage there too
// makes the lit images agree but the shadow atlases' depth no longer bit-identical (docs/rhi.md).
std::vector<parity::Picture> renderEdgeTie(rhi::Device& device, const rhi::NamedConfiguration&)
{
    const glm::vec4 red(1, 0, 0, 1), green(0, 1, 0, 1);
    const float edge = 1.0f - 7.5f / 8.0f;
    const std::vector<pattern::PatternVertex> triangles{
        {{-1.0f, edge, 5.0f}, red},  {{1.0f, edge, 5.0f}, red},    {{0.0f, 1.0f, 5.0f}, red},
        {{1.0f, edge, 5.0f}, green}, {{-1.0f, edge, 5.0f}, green}, {{0.0f, -1.0f, 5.0f}, green},
    };
    pattern::PatternRenderer renderer(device, {.width = 16, .height = 16});
    renderer.render(triangles);
    return {parity::colorPicture("edge-tie", renderer.color())};
}

TEST(ParityTest, CentresOnAnEdgeGoToTheTriangleEachRasterizerRulePicks)
{
    const std::vector<parity::ConfigurationRun> runs = parity::renderConfigurations(renderEdgeTie);
    for (const parity::ConfigurationRun& run : runs) {
        if (run.status != parity::ConfigurationRun::Status::Rendered)
            continue;
        const bool upperLeft = run.name() == "opengl" || run.name() == "opengl-reversed";
        const parity::Picture& picture = run.picture("edge-tie");
        for (std::uint32_t x = 0; x < picture.width(); ++x) {
            const std::size_t texel = (std::size_t(picture.width()) * 7 + x) * 4;
            EXPECT_EQ(std::uint8_t(picture.color.bytes[texel]), upperLeft ? 255u : 0u) << run.name() << " x " << x;
            EXPECT_EQ(std::uint8_t(picture.color.bytes[texel + 1]), upperLeft ? 0u : 255u) << run.name() << " x " << x;
        }
    }
}

TEST(ParityTest, ReversedZBeatsTheStandardMappingAtDistance)
{
    int worstReversed = -1, bestStandard = -1;
    const std::vector<SkippedConfiguration> skipped =
        forEachConfiguration([&](rhi::Device& device, const std::string& name) {
            const ZFighting z = countZFighting(device);
            std::cout << fmt::format("[ z-fighting ] {}: {} of {} pixels\n", name, z.fighting, z.pixels);
            const bool precise =
                device.conventions().reversedZ() && device.conventions().depthRange() == rhi::DepthRange::ZeroToOne;
            int& slot = precise ? worstReversed : bestStandard;
            slot = slot < 0 ? z.fighting : (precise ? std::max(slot, z.fighting) : std::min(slot, z.fighting));
        });
    ASSERT_GE(worstReversed, 0);
    ASSERT_GE(bestStandard, 0);
    EXPECT_LT(worstReversed, bestStandard);
    reportSkipped(skipped);
}

} // namespace
} // namespace penumbra::testing
