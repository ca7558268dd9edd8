// Backend parity of contact shadows (shadows.contact): the contact scene's lit image at 160 x 90 with a 512-texel
// atlas, forward and on the screen-space path with 4x MSAA, through every configuration, compared by the parity
// harness. The march reads depth through the RHI's conventions only, so it must find the same occluders everywhere.
#include "GpuTesting.hpp"
#include "ShadowScene.hpp"

#include "penumbra/parity/GoogleTest.hpp"

#include <gtest/gtest.h>

namespace penumbra {
namespace {

render::FrameDesc contactParityFrame(std::uint32_t msaa, render::ShadowPath path)
{
    render::FrameDesc frame;
    frame.width = 160;
    frame.height = 90;
    frame.msaa = msaa;
    frame.shadowPath = path;
    frame.shadows.directional.atlasSize = 512;
    frame.shadows.local.atlasSize = 512;
    frame.shadows.contact.shadows = shadows::Toggle::On;
    return frame;
}

const std::vector<parity::ConfigurationRun>& contactRuns()
{
    static const std::vector<parity::ConfigurationRun> runs =
        parity::renderConfigurations([](rhi::Device& device, const rhi::NamedConfiguration& configuration) {
            const scene::Scene scene = apps::namedScene("contact");
            const apps::ShadowPictures forward =
                apps::renderShadowScene(device, configuration.name, scene,
                                        contactParityFrame(1, render::ShadowPath::Forward), false);
            const apps::ShadowPictures msaa =
                apps::renderShadowScene(device, configuration.name, scene,
                                        contactParityFrame(4, render::ShadowPath::ScreenSpace), false);
            testing::savePicture(forward.lit, "contact-parity-" + configuration.name);
            return std::vector{parity::colorPicture("lit-contact", forward.lit),
                               parity::colorPicture("lit-contact-msaa4-screen-space", msaa.lit)};
        });
    return runs;
}

TEST(ContactParity, ContactShadowsAgreeEverywhere) { PENUMBRA_EXPECT_PARITY(contactRuns(), parity::Options{}); }

} // namespace
} // namespace penumbra
