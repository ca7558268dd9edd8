// The parity report's verdicts on made-up pictures: which pairs pass, what the failures name, what the
// heat maps show. CPU only; the commands that render real pictures are tested in cli.parity-*.
#include "penumbra/parity/HeatMap.hpp"
#include "ParityReport.hpp"

#include <gtest/gtest.h>

namespace penumbra::apps {
namespace {

rhi::Image grey(std::uint8_t value)
{
    return {4, 2, rhi::Format::RGBA8, std::vector<std::byte>(4 * 2 * 4, std::byte{value})};
}

ShadowPictures pictures(const std::string& configuration, std::uint8_t litValue, float lightDepth, bool reversedZ)
{
    ShadowPictures p;
    p.configuration = configuration;
    p.reversedZ = reversedZ;
    p.lit = grey(litValue);
    AtlasPictures atlas{"directional", grey(0), {2, 2, std::vector<float>(4, reversedZ ? 0.5f : 0.25f)},
                        std::vector<float>(4, lightDepth)};
    p.atlases.push_back(atlas);
    return p;
}

TEST(ParityReportTest, EveryPairWithinTheThresholdsPasses)
{
    const std::vector<ShadowPictures> all = {pictures("a", 100, 0.5f, false), pictures("b", 100, 0.5f, false),
                                             pictures("c", 100, 0.5f + 1e-5f, true)};
    const ParityReport report = compareParity(all, {grey(7), grey(7), grey(7)});
    ASSERT_EQ(report.pairs.size(), 3u);
    EXPECT_TRUE(report.pass);
    EXPECT_EQ(report.pairs[0].atlases[0].rawIdentical, true);       // a, b: same conventions
    EXPECT_FALSE(report.pairs[1].atlases[0].rawIdentical.has_value()); // a, c: reversed-Z differs
    EXPECT_EQ(report.failures(all), "");
    EXPECT_NE(report.summary(all).find("within the thresholds"), std::string::npos) << report.summary(all);
}

TEST(ParityReportTest, APairBeyondAThresholdFailsAndIsNamed)
{
    const std::vector<ShadowPictures> all = {pictures("vulkan", 100, 0.5f, false),
                                             pictures("opengl", 140, 0.5f + 1e-3f, false)};
    const ParityReport report = compareParity(all, {grey(7), grey(8)});
    EXPECT_FALSE(report.pass);
    EXPECT_FALSE(report.pairs[0].pass);
    const std::string failures = report.failures(all);
    EXPECT_NE(failures.find("vulkan vs opengl: lit PSNR"), std::string::npos) << failures;
    EXPECT_NE(failures.find("vulkan vs opengl: directional atlas light-depth difference 0.001"), std::string::npos)
        << failures;
    EXPECT_NE(failures.find("opengl: test pattern differs from vulkan's"), std::string::npos) << failures;
}

TEST(ParityReportTest, HeatMapsAreBlackWhereEqualAndSaturateAtFullScale)
{
    rhi::Image a = grey(10), b = grey(10);
    b.bytes[4] = std::byte{11};  // pixel 1: one step
    b.bytes[8] = std::byte{200}; // pixel 2: far beyond full scale
    const rhi::Image map = parity::differenceHeatMap(a, b, 8);
    EXPECT_EQ(map.bytes[0], std::byte{0});
    EXPECT_GT(map.bytes[4], std::byte{0}) << "a single step stays visible";
    EXPECT_EQ(map.bytes[8 + 0], std::byte{255});
    EXPECT_EQ(map.bytes[8 + 1], std::byte{255});
    EXPECT_EQ(map.bytes[8 + 2], std::byte{255});

    const std::vector<float> x = {0.0f, 0.5f}, y = {0.0f, 0.5001f};
    const rhi::Image floats = parity::differenceHeatMap(x, y, 2, 1, 1e-4f);
    EXPECT_EQ(floats.bytes[0], std::byte{0});
    EXPECT_EQ(floats.bytes[4], std::byte{255});
}

} // namespace
} // namespace penumbra::apps
