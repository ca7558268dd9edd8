// The parity harness through the real drivers: a render function on fresh validated devices of
// every configuration, one that throws on one configuration, unknown names, and the GoogleTest
// helper on pictures that agree and on a deliberately different one.
#include "GpuTesting.hpp"

#include "penumbra/parity/GoogleTest.hpp"
#include "penumbra/rhi/Error.hpp"

#include <filesystem>
#include <gtest/gtest-spi.h>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kSize = 16;

// A render target cleared to `color` and read back.
rhi::Image cleared(rhi::Device& device, const glm::vec4& color)
{
    auto target = device.createTexture({.width = kSize, .height = kSize, .usage = rhi::TextureUsage::RenderTarget});
    const rhi::Attachment attachment{target.get(), 0};
    auto framebuffer = device.createFramebuffer({.colors = {&attachment, 1}});
    auto commands = device.createCommandList();
    commands->beginPass({.framebuffer = framebuffer.get(), .clearColor = color});
    commands->endPass();
    device.submit(*commands);
    return rhi::readTexture(device, *target);
}

std::vector<parity::Picture> grey(rhi::Device& device, const rhi::NamedConfiguration&)
{
    return {parity::colorPicture("colour", cleared(device, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)))};
}

// Red on opengl only: the deliberately different picture.
std::vector<parity::Picture> redOnOpenGl(rhi::Device& device, const rhi::NamedConfiguration& configuration)
{
    const bool red = configuration.name == "opengl";
    return {
        parity::colorPicture("colour", cleared(device, red ? glm::vec4(1, 0, 0, 1) : glm::vec4(0.5f, 0.5f, 0.5f, 1)))};
}

TEST(ParityHarness, RunsEveryConfigurationOnAValidatedDevice)
{
    std::vector<std::string> seen;
    const parity::Result result = parity::run([&](rhi::Device& device, const rhi::NamedConfiguration& c) {
        EXPECT_TRUE(device.desc().validation) << c.name;
        seen.push_back(c.name);
        return grey(device, c);
    });
    EXPECT_EQ(seen, compiledConfigurations());
    EXPECT_TRUE(result.pass());
    EXPECT_EQ(result.pairs.size(), seen.size() * (seen.size() - 1) / 2);
}

TEST(ParityHarness, ARenderFunctionThrowingOnOneConfigurationIsReportedAndTheOthersCompared)
{
    const parity::Result result = parity::run([](rhi::Device& device, const rhi::NamedConfiguration& c) {
        if (c.name == "opengl-noclip")
            throw rhi::Error("this pass needs clip control");
        return grey(device, c);
    });
    EXPECT_FALSE(result.pass());
    const parity::ConfigurationRun& failed = result.configuration("opengl-noclip");
    EXPECT_EQ(failed.status, parity::ConfigurationRun::Status::Failed);
    EXPECT_EQ(failed.message, "the render function threw: this pass needs clip control");
    const std::size_t others = compiledConfigurations().size() - 1;
    EXPECT_EQ(result.pairs.size(), others * (others - 1) / 2);
    for (const parity::PairResult& pair : result.pairs)
        EXPECT_TRUE(pair.pass()) << result.pairName(pair);
    ASSERT_EQ(result.failures().size(), 1u);
    EXPECT_EQ(result.failures()[0], "opengl-noclip: the render function threw: this pass needs clip control");
}

TEST(ParityHarness, AnUnknownConfigurationIsRefusedBeforeAnythingRenders)
{
    bool rendered = false;
    try {
        parity::run(
            [&](rhi::Device& device, const rhi::NamedConfiguration& c) {
                rendered = true;
                return grey(device, c);
            },
            {.configurations = {"vulkan", "direct3d"}});
        ADD_FAILURE() << "an unknown configuration was accepted";
    } catch (const rhi::Error& e) {
        EXPECT_NE(std::string(e.what()).find("unknown configuration 'direct3d'; valid configurations: vulkan"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(rendered);
    EXPECT_THROW(parity::run(grey, {.configurations = {"vulkan"},
                                    .pairing = parity::Pairing::AgainstReference,
                                    .reference = "opengl"}),
                 rhi::Error);
}

TEST(ParityHarness, TheGoogleTestHelperPassesPicturesThatAgree)
{
    std::filesystem::remove_all(parity::testing::reportFolder());
    const parity::Result result = PENUMBRA_EXPECT_PARITY(grey);
    EXPECT_TRUE(result.pass());
    EXPECT_FALSE(std::filesystem::exists(parity::testing::reportFolder())) << "a report without a failure";
}

void expectRedOnOpenGlToMatch() { PENUMBRA_EXPECT_PARITY(redOnOpenGl, {.configurations = {"vulkan", "opengl"}}); }

TEST(ParityHarness, TheGoogleTestHelperFailsNamingThePairAndWritesTheReport)
{
    std::filesystem::remove_all(parity::testing::reportFolder());
    EXPECT_NONFATAL_FAILURE(expectRedOnOpenGlToMatch(),
                            "vulkan vs opengl beyond the parity thresholds:\n  colour: max difference 128 > 0");
    for (const char* file : {"index.html", "parity.json", "diff/vulkan-vs-opengl-colour.png", "opengl/colour.png"})
        EXPECT_TRUE(std::filesystem::exists(parity::testing::reportFolder() / file)) << file;
}

} // namespace
} // namespace penumbra::testing
