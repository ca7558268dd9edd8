// Backend parity of a picture of many lights (issue 40): ManyLightsScene's 300 spot and point lights through every
// configuration, the lit pictures compared by the parity harness. Each light's cluster list is built on the CPU from
// the same camera whatever the backend; measured, the pictures are byte-identical in every pair of configurations (a
// flat ground seen from above has no edge where the rasterisers could differ), and the test holds them to that.
#include "GpuTesting.hpp"
#include "ManyLightsScene.hpp"
#include "ShadowScene.hpp"

#include "penumbra/parity/GoogleTest.hpp"
#include "penumbra/scene/LocalLights.hpp"

#include <gtest/gtest.h>

namespace penumbra {
namespace {

render::FrameDesc manyLightsFrame()
{
    render::FrameDesc frame;
    frame.width = 320;
    frame.height = 180;
    frame.shadows.directional.atlasSize = 512;
    frame.shadows.local.atlasSize = 512;
    return frame;
}

const std::vector<parity::ConfigurationRun>& manyLightsRuns()
{
    static const std::vector<parity::ConfigurationRun> runs =
        parity::renderConfigurations([](rhi::Device& device, const rhi::NamedConfiguration& configuration) {
            const apps::ShadowPictures pictures =
                apps::renderShadowScene(device, configuration.name, testing::manyLightsScene().scene, manyLightsFrame(),
                                        false);
            testing::savePicture(pictures.lit, "many-lights-parity-" + configuration.name);
            return std::vector{parity::colorPicture("lit-many-lights", pictures.lit)};
        });
    return runs;
}

parity::Options manyLightsParityOptions()
{
    parity::Options options;
    options.pairThresholds = [](const std::string&, const parity::ConfigurationRun&, const parity::ConfigurationRun&,
                                const parity::Thresholds&) { return parity::identical(); };
    return options;
}

TEST(ManyLightsParity, LitPicturesAgreeEverywhere)
{
    PENUMBRA_EXPECT_PARITY(manyLightsRuns(), manyLightsParityOptions());
}

// The negative control: the same frame with only the first 16 local lights (the old limit), against the first
// configuration's picture, is caught by the thresholds.
TEST(ManyLightsParity, TheSixteenLightLimitCatchesFault)
{
    const parity::ConfigurationRun& first = manyLightsRuns().front();
    ASSERT_EQ(first.status, parity::ConfigurationRun::Status::Rendered) << first.message;
    scene::Scene limited = testing::manyLightsScene().scene;
    scene::keepFirstLocalLights(limited, 16);
    const apps::ShadowPictures pictures = apps::renderShadowScene(first.name(), limited, manyLightsFrame());
    const parity::Picture sixteen = parity::colorPicture("lit-many-lights", pictures.lit);
    const parity::Thresholds bound = parity::identical();
    EXPECT_TRUE(parity::comparePictures(first.picture("lit-many-lights"), first.conventions(),
                                        first.picture("lit-many-lights"), first.conventions(), bound)
                    .pass());
    EXPECT_FALSE(parity::comparePictures(first.picture("lit-many-lights"), first.conventions(), sixteen,
                                         first.conventions(), bound)
                     .pass());
}

} // namespace
} // namespace penumbra
