// Backend parity of the resolved lit image with 4x MSAA (FrameDesc::msaa): the test scene at 128 x 128 through every
// configuration, the resolved pictures compared by the parity harness. Where the shadow parity tests allow one pixel
// across backends, the edges here allow a few more: each backend averages the samples of an edge pixel in its own
// rounding, and GL without clip control flips the vertical sample pattern with the picture (GlOrientation).
#include "GpuTesting.hpp"
#include "ShadowScene.hpp"

#include "penumbra/parity/GoogleTest.hpp"
#include "penumbra/render/LitUniforms.hpp"

#include <gtest/gtest.h>

namespace penumbra {
namespace {

constexpr std::uint32_t kSize = 128;
constexpr std::uint32_t kSamples = 4; // offered by every configuration here (MultisampleTest)

render::FrameDesc msaaFrame()
{
    render::FrameDesc frame;
    frame.width = kSize;
    frame.height = kSize;
    frame.msaa = kSamples;
    frame.shadows.directional.atlasSize = 512;
    frame.shadows.other.atlasSize = 512;
    return frame;
}

const std::vector<parity::ConfigurationRun>& msaaRuns()
{
    static const std::vector<parity::ConfigurationRun> runs =
        parity::renderConfigurations([](rhi::Device& device, const rhi::NamedConfiguration& configuration) {
            const apps::ShadowPictures pictures = apps::renderShadowScene(
                device, configuration.name, apps::namedScene("test"), msaaFrame(), false);
            testing::savePicture(pictures.lit, "msaa-parity-" + configuration.name);
            return std::vector{parity::colorPicture("lit-msaa4", pictures.lit)};
        });
    return runs;
}

bool sameBackend(const std::string& a, const std::string& b)
{
    return a.substr(0, a.find('-')) == b.substr(0, b.find('-'));
}

parity::Options msaaParityOptions()
{
    parity::Options options;
    options.pairThresholds = [](const std::string&, const parity::ConfigurationRun& a,
                                const parity::ConfigurationRun& b, const parity::Thresholds&) {
        return sameBackend(a.name(), b.name())
                   ? parity::Thresholds{.maxDifference = parity::kAnyDifference, .minPsnr = 50.0,
                                        .maxDifferingPixels = 16}
                   : parity::Thresholds{.maxDifference = parity::kAnyDifference, .minPsnr = 40.0,
                                        .maxDifferingPixels = 160};
    };
    return options;
}

TEST(MsaaParity, ResolvedLitImagesAgreeEverywhere) { PENUMBRA_EXPECT_PARITY(msaaRuns(), msaaParityOptions()); }

} // namespace
} // namespace penumbra
