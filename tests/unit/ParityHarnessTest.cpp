// The parity harness's comparisons and report on made-up pictures (CPU only): what passes, what each
// threshold catches, how mismatched pictures and failed configurations are reported, what the heat
// maps show. tests/parity/HarnessTest.cpp runs it through the real drivers.
#include "penumbra/parity/Harness.hpp"
#include "penumbra/parity/HeatMap.hpp"
#include "penumbra/parity/Report.hpp"
#include "penumbra/render/AtlasPicture.hpp"
#include "penumbra/rhi/Error.hpp"

#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

namespace penumbra::parity {
namespace {

rhi::Image grey(std::uint8_t value, std::uint32_t width = 4, std::uint32_t height = 2)
{
    return {width, height, rhi::Format::RGBA8,
            std::vector<std::byte>(std::size_t(width) * height * 4, std::byte{value})};
}

// A configuration's desc as its name says, whichever backends this build has: the comparisons need only the
// conventions.
rhi::NamedConfiguration named(const std::string& configuration)
{
    return {configuration,
            {.backend = configuration.starts_with("vulkan") ? "vulkan" : "opengl",
             .depthRange = configuration.find("noclip") != std::string::npos ? rhi::DepthRange::MinusOneToOne
                                                                             : rhi::DepthRange::ZeroToOne,
             .reversedZ = configuration.ends_with("-reversed")}};
}

ConfigurationRun made(const std::string& configuration, std::vector<Picture> pictures)
{
    return {named(configuration), ConfigurationRun::Status::Rendered, {}, std::move(pictures)};
}

std::string joined(const std::vector<std::string>& lines)
{
    std::string text;
    for (const std::string& line : lines)
        text += line + "\n";
    return text;
}

TEST(ParityHarnessTest, IdenticalPicturesPassEveryPair)
{
    const Result result = compare({made("vulkan", {colorPicture("colour", grey(100))}),
                                   made("opengl", {colorPicture("colour", grey(100))}),
                                   made("opengl-noclip", {colorPicture("colour", grey(100))})});
    ASSERT_EQ(result.pairs.size(), 3u);
    EXPECT_TRUE(result.pass()) << joined(result.failures());
    EXPECT_TRUE(result.failures().empty());
    EXPECT_NE(result.summary().find("colour: max diff 0, identical"), std::string::npos) << result.summary();
}

TEST(ParityHarnessTest, DeliberatelyDifferentPicturesFailNamingThePair)
{
    rhi::Image changed = grey(100);
    changed.bytes[5] = std::byte{140}; // one pixel, one channel, 40 steps
    const Result result = compare(
        {made("vulkan", {colorPicture("colour", grey(100))}), made("opengl", {colorPicture("colour", changed)})});
    EXPECT_FALSE(result.pass());
    const PictureComparison& c = result.pairs.at(0).pictures.at(0);
    EXPECT_EQ(c.figures.maxDifference, 40.0);
    EXPECT_EQ(c.figures.differingPixels, 1u);
    EXPECT_EQ(c.figures.pixels, 8u);
    ASSERT_EQ(result.failures().size(), 1u);
    EXPECT_EQ(result.failures()[0], "vulkan vs opengl: colour: max difference 40 > 0");

    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / fmt::format("penumbra-parity-report-{}", ::getpid());
    writeReport(folder, result, "made-up <pictures>");
    for (const char* file :
         {"index.html", "parity.json", "vulkan/colour.png", "opengl/colour.png", "diff/vulkan-vs-opengl-colour.png"})
        EXPECT_TRUE(std::filesystem::exists(folder / file)) << file;
    const nlohmann::json json = nlohmann::json::parse(std::ifstream(folder / "parity.json"));
    EXPECT_EQ(json["pass"], false);
    EXPECT_EQ(json["pairs"][0]["a"], "vulkan");
    EXPECT_EQ(json["pairs"][0]["pictures"][0]["maxDifference"], 40.0);
    EXPECT_EQ(json["pairs"][0]["pictures"][0]["failures"][0], "max difference 40 > 0");
    std::ifstream page(folder / "index.html");
    const std::string html((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
    EXPECT_NE(html.find("made-up &lt;pictures&gt;"), std::string::npos);
    std::filesystem::remove_all(folder);
}

TEST(ParityHarnessTest, EachThresholdLoosensOnItsOwn)
{
    rhi::Image changed = grey(100);
    changed.bytes[0] = std::byte{102};
    changed.bytes[4] = std::byte{101};
    const Picture a = colorPicture("colour", grey(100));
    const Picture b = colorPicture("colour", changed);
    const rhi::Conventions conventions(rhi::DepthRange::ZeroToOne, false);
    EXPECT_FALSE(comparePictures(a, conventions, b, conventions).pass());
    EXPECT_TRUE(comparePictures(a, conventions, b, conventions, {.maxDifference = 2}).pass());
    const PictureComparison twoPixels =
        comparePictures(a, conventions, b, conventions, {.maxDifference = 2, .maxDifferingPixels = 1});
    ASSERT_EQ(twoPixels.failures.size(), 1u);
    EXPECT_EQ(twoPixels.failures[0], "2 of 8 pixels differ > 1");
    const PictureComparison psnr = comparePictures(a, conventions, b, conventions, {.maxDifference = 2, .minPsnr = 60});
    ASSERT_EQ(psnr.failures.size(), 1u);
    EXPECT_NE(psnr.failures[0].find("PSNR 56.2 dB < 60 dB"), std::string::npos) << psnr.failures[0];
    const PictureComparison own =
        comparePictures(a, conventions, a, conventions,
                        {.check = [](const Picture&, const rhi::Conventions&, const Picture&, const rhi::Conventions&) {
                            return std::optional<std::string>("the test's own reason");
                        }});
    ASSERT_EQ(own.failures.size(), 1u);
    EXPECT_EQ(own.failures[0], "the test's own reason");
}

TEST(ParityHarnessTest, MismatchedSizesAndFormatsAreReportedNotCompared)
{
    rhi::Image srgb = grey(100);
    srgb.format = rhi::Format::RGBA8_SRGB;
    const Result result =
        compare({made("vulkan", {colorPicture("colour", grey(100)), colorPicture("encoded", grey(9))}),
                 made("opengl", {colorPicture("colour", grey(100, 2, 2)), colorPicture("encoded", srgb)})});
    EXPECT_FALSE(result.pass());
    const std::string failures = joined(result.failures());
    EXPECT_NE(failures.find("vulkan vs opengl: colour: sizes differ: RGBA8 4x2 and RGBA8 2x2"), std::string::npos)
        << failures;
    EXPECT_NE(failures.find("vulkan vs opengl: encoded: formats differ: RGBA8 4x2 and RGBA8_SRGB 4x2"),
              std::string::npos)
        << failures;
}

TEST(ParityHarnessTest, APictureOnlyOneConfigurationRenderedFails)
{
    const Result result = compare({made("vulkan", {colorPicture("colour", grey(1)), colorPicture("extra", grey(1))}),
                                   made("opengl", {colorPicture("colour", grey(1))})});
    ASSERT_EQ(result.failures().size(), 1u);
    EXPECT_EQ(result.failures()[0], "vulkan vs opengl: extra: vulkan rendered it, opengl did not");
}

TEST(ParityHarnessTest, AFailedConfigurationIsReportedAndTheOthersCompared)
{
    const ConfigurationRun failed{named("opengl"),
                                  ConfigurationRun::Status::Failed,
                                  "the render function threw: no",
                                  {}};
    const ConfigurationRun unsupported{named("opengl-noclip"),
                                       ConfigurationRun::Status::Unsupported,
                                       "no clip control",
                                       {}};
    const Result result = compare({made("vulkan", {colorPicture("colour", grey(1))}), failed, unsupported,
                                   made("vulkan-reversed", {colorPicture("colour", grey(1))})});
    ASSERT_EQ(result.pairs.size(), 1u);
    EXPECT_EQ(result.pairName(result.pairs[0]), "vulkan vs vulkan-reversed");
    EXPECT_TRUE(result.pairs[0].pass());
    EXPECT_FALSE(result.pass());
    ASSERT_EQ(result.failures().size(), 1u) << "unsupported configurations do not fail";
    EXPECT_EQ(result.failures()[0], "opengl: the render function threw: no");
}

TEST(ParityHarnessTest, AgainstAReferenceComparesEachConfigurationWithIt)
{
    std::vector<ConfigurationRun> runs;
    for (const char* name : {"vulkan", "vulkan-reversed", "opengl", "opengl-reversed"})
        runs.push_back(made(name, {colorPicture("colour", grey(1))}));
    const Result result = compare(runs, {.pairing = Pairing::AgainstReference, .reference = "opengl"});
    ASSERT_EQ(result.pairs.size(), 3u);
    for (const PairResult& pair : result.pairs)
        EXPECT_EQ(result.configurations[pair.a].name(), "opengl");
    EXPECT_THROW(compare(runs, {.pairing = Pairing::AgainstReference, .reference = "opengl-noclip"}), rhi::Error);
}

// One depth of 0.25 (standard) is 0.75 reversed: the same distance from the far plane.
TEST(ParityHarnessTest, DepthFromTheFarPlaneAgreesAcrossConventionsAndIsBitExactWithin)
{
    const auto depth = [](float d) { return depthPicture("depth", rhi::DepthImage{2, 1, {d, 1.0f}}); };
    const auto reversed = [](float d) { return depthPicture("depth", rhi::DepthImage{2, 1, {d, 0.0f}}); };
    const Result result = compare({made("vulkan", {depth(0.25f)}), made("vulkan-reversed", {reversed(0.75f)}),
                                   made("opengl", {depth(std::nextafter(0.25f, 1.0f))})});
    const PictureComparison& across = result.pair("vulkan", "vulkan-reversed")->pictures.at(0);
    EXPECT_TRUE(across.pass()) << joined(across.failures);
    EXPECT_FALSE(across.figures.rawDifferingTexels.has_value());
    EXPECT_EQ(across.figures.coverageMismatches, 0u);
    const PictureComparison& same = result.pair("vulkan", "opengl")->pictures.at(0);
    ASSERT_EQ(same.figures.rawDifferingTexels, 1u);
    EXPECT_FALSE(same.pass());
    EXPECT_TRUE(comparePictures(depth(0.25f), {rhi::DepthRange::ZeroToOne, false}, depth(std::nextafter(0.25f, 1.0f)),
                                {rhi::DepthRange::ZeroToOne, false},
                                {.maxDifference = 1e-6, .bitExactWhereConventionsAgree = false})
                    .pass());
    // A texel drawn in one picture and at the far plane in the other.
    const PictureComparison uncovered = comparePictures(depth(0.25f), {rhi::DepthRange::ZeroToOne, false}, depth(1.0f),
                                                        {rhi::DepthRange::ZeroToOne, false}, {.maxDifference = 1});
    EXPECT_EQ(uncovered.figures.coverageMismatches, 1u);
    EXPECT_FALSE(uncovered.pass());
}

// A caster crossing an orthographic tile's far plane: a depth within the far plane's rounding in [0, 1] (under 2^-25
// from it) is the clear in a standard-Z atlas, so it is the far plane in the reversed-Z one too; a little farther from
// it, it stays drawn.
TEST(ParityHarnessTest, AtlasDepthWithinTheFarPlanesRoundingIsTheFarPlane)
{
    const rhi::Conventions standard(rhi::DepthRange::ZeroToOne, false);
    const rhi::Conventions reversed(rhi::DepthRange::ZeroToOne, true);
    const std::vector<float> background = render::lightDepthFraction(rhi::DepthImage{1, 1, {1.0f}}, standard);
    EXPECT_EQ(render::lightDepthFraction(rhi::DepthImage{1, 1, {1.6e-9f}}, reversed), background);
    EXPECT_GT(render::lightDepthFraction(rhi::DepthImage{1, 1, {1e-6f}}, reversed).at(0), 0.0f);
}

TEST(ParityHarnessTest, LinearViewDepthAgreesAcrossDepthRanges)
{
    const rhi::Conventions zeroToOne(rhi::DepthRange::ZeroToOne, false);
    const rhi::Conventions minusOneToOne(rhi::DepthRange::MinusOneToOne, true);
    const auto at = [](const rhi::Conventions& c, float viewDepth) {
        const glm::mat4 projection = c.perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
        return viewDepthPicture("depth", {1, 1, {c.windowDepth(projection, viewDepth)}}, projection);
    };
    const PictureComparison c = comparePictures(at(zeroToOne, 7.0f), zeroToOne, at(minusOneToOne, 7.0f), minusOneToOne,
                                                {.maxDifference = 1e-3});
    EXPECT_TRUE(c.pass()) << joined(c.failures);
    EXPECT_LT(c.figures.maxDifference, 1e-3);
    EXPECT_FALSE(
        comparePictures(at(zeroToOne, 7.0f), zeroToOne, at(minusOneToOne, 7.1f), minusOneToOne, {.maxDifference = 1e-3})
            .pass());
}

TEST(ParityHarnessTest, BadPicturesAreRefusedByName)
{
    EXPECT_THROW(validate(colorPicture("a/b", grey(1))), rhi::Error);
    EXPECT_THROW(validate(colorPicture("", grey(1))), rhi::Error);
    rhi::Image short_ = grey(1);
    short_.bytes.pop_back();
    try {
        validate(colorPicture("colour", short_));
        ADD_FAILURE() << "a picture with a byte missing passed";
    } catch (const rhi::Error& e) {
        EXPECT_NE(std::string(e.what()).find("picture 'colour': 31 bytes for RGBA8 4x2 (32 expected)"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(validate(floatPicture("values", 2, 2, {1.0f})), rhi::Error);
}

TEST(ParityHarnessTest, HeatMapsAreBlackWhereEqualAndSaturateAtFullScale)
{
    rhi::Image a = grey(10), b = grey(10);
    b.bytes[4] = std::byte{11}; // pixel 1: one step
    b.bytes[8] = std::byte{200}; // pixel 2: far beyond full scale
    const rhi::Image map = differenceHeatMap(a, b, 8);
    EXPECT_EQ(map.bytes[0], std::byte{0});
    EXPECT_GT(map.bytes[4], std::byte{0}) << "a single step stays visible";
    EXPECT_EQ(map.bytes[8 + 0], std::byte{255});
    EXPECT_EQ(map.bytes[8 + 1], std::byte{255});
    EXPECT_EQ(map.bytes[8 + 2], std::byte{255});

    const std::vector<float> x = {0.0f, 0.5f}, y = {0.0f, 0.5001f};
    const rhi::Image floats = differenceHeatMap(x, y, 2, 1, 1e-4f);
    EXPECT_EQ(floats.bytes[0], std::byte{0});
    EXPECT_EQ(floats.bytes[4], std::byte{255});
}

} // namespace
} // namespace penumbra::parity
