// Backend parity of the resolved lit image with 4x MSAA (FrameDesc::msaa): the test scene at 128 x 128 through every
// configuration, the resolved pictures compared by the parity harness. lavapipe and llvmpipe place and average the
// samples alike: measured, byte-identical between vulkan and opengl-noclip and between reversed twins, 1 pixel of
// 16 384 one level apart between vulkan and opengl (with clip control), as without MSAA.
#include "GpuTesting.hpp"
#include "ShadowScene.hpp"

#include "penumbra/parity/GoogleTest.hpp"
#include "penumbra/render/LitUniforms.hpp"

#include <gtest/gtest.h>

namespace penumbra {
namespace {

constexpr std::uint32_t kMsaaParitySize = 128;
constexpr std::uint32_t kSamples = 4; // offered by every configuration here (MultisampleTest)

render::FrameDesc msaaFrame()
{
    render::FrameDesc frame;
    frame.width = kMsaaParitySize;
    frame.height = kMsaaParitySize;
    frame.msaa = kSamples;
    frame.shadows.directional.atlasSize = 512;
    frame.shadows.local.atlasSize = 512;
    return frame;
}

const std::vector<parity::ConfigurationRun>& msaaRuns()
{
    static const std::vector<parity::ConfigurationRun> runs =
        parity::renderConfigurations([](rhi::Device& device, const rhi::NamedConfiguration& configuration) {
            const apps::ShadowPictures pictures =
                apps::renderShadowScene(device, configuration.name, apps::namedScene("test"), msaaFrame(), false);
            testing::savePicture(pictures.lit, "msaa-parity-" + configuration.name);
            return std::vector{parity::colorPicture("lit-msaa4", pictures.lit)};
        });
    return runs;
}

parity::Thresholds msaaThresholds(const std::string& a, const std::string& b)
{
    return testing::reversedTwins(a, b) ? parity::identical()
                                        : parity::Thresholds{.maxDifference = 1.0, .maxDifferingPixels = 2};
}

parity::Options msaaParityOptions()
{
    parity::Options options;
    options.pairThresholds = [](const std::string&, const parity::ConfigurationRun& a,
                                const parity::ConfigurationRun& b,
                                const parity::Thresholds&) { return msaaThresholds(a.name(), b.name()); };
    return options;
}

TEST(MsaaParity, ResolvedLitImagesAgreeEverywhere) { PENUMBRA_EXPECT_PARITY(msaaRuns(), msaaParityOptions()); }

// The negative control: the same frame without MSAA, against the first configuration's resolved picture, is caught by
// the thresholds between backends (its edges differ in hundreds of pixels).
TEST(MsaaParity, TheThresholdsTellMsaaFromNone)
{
    const parity::ConfigurationRun& first = msaaRuns().front();
    ASSERT_EQ(first.status, parity::ConfigurationRun::Status::Rendered) << first.message;
    render::FrameDesc frame = msaaFrame();
    frame.msaa = 1;
    const apps::ShadowPictures single = apps::renderShadowScene(first.name(), apps::namedScene("test"), frame);
    const parity::Picture none = parity::colorPicture("lit-msaa4", single.lit);
    const parity::Thresholds bound = msaaThresholds("vulkan", "opengl");
    EXPECT_TRUE(parity::comparePictures(first.picture("lit-msaa4"), first.conventions(), first.picture("lit-msaa4"),
                                        first.conventions(), bound)
                    .pass());
    EXPECT_FALSE(
        parity::comparePictures(first.picture("lit-msaa4"), first.conventions(), none, first.conventions(), bound)
            .pass());
}

} // namespace
} // namespace penumbra
