// Backend parity of contact shadows (shadows.contact): the contact scene's lit image at 160 x 90 with a 512-texel
// atlas, forward and on the screen-space path with 4x MSAA, through every configuration, compared by the parity
// harness, from the scene's camera straight above and from the low camera of the contact-local scene, whose spot and
// point light the march goes towards too. The march reads the prepass's view depth, which no depth convention
// changes, so it must find the same occluders everywhere, pixel for pixel (a march through the depth buffer differed
// by 1 to 39 pixels from the low camera, docs/notes/2026-12-07-contact-parity-cost.md).
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

// From low over the shadowed side: the sun's contact shadows (the contact scene) and the spot and point lights'
// (contact-local), forward, on the screen-space path with 4x MSAA and forward with 4x MSAA.
const std::vector<parity::ConfigurationRun>& lowCameraContactRuns()
{
    static const std::vector<parity::ConfigurationRun> runs =
        parity::renderConfigurations([](rhi::Device& device, const rhi::NamedConfiguration& configuration) {
            const scene::Scene local = apps::namedScene("contact-local");
            scene::Scene sun = apps::namedScene("contact");
            sun.camera = local.camera;
            const auto lit = [&](const scene::Scene& scene, std::uint32_t msaa, render::ShadowPath path) {
                render::FrameDesc frame = contactParityFrame(msaa, path);
                frame.shadows.contact.localLights = 2;
                return apps::renderShadowScene(device, configuration.name, scene, frame, false).lit;
            };
            return std::vector{parity::colorPicture("lit-sun-low", lit(sun, 1, render::ShadowPath::Forward)),
                               parity::colorPicture("lit-local-low", lit(local, 1, render::ShadowPath::Forward)),
                               parity::colorPicture("lit-local-low-msaa4-screen-space",
                                                    lit(local, 4, render::ShadowPath::ScreenSpace)),
                               parity::colorPicture("lit-local-low-msaa4", lit(local, 4, render::ShadowPath::Forward))};
        });
    return runs;
}

TEST(ContactParity, ContactShadowsAgreeEverywhere) { PENUMBRA_EXPECT_PARITY(contactRuns(), parity::Options{}); }

TEST(ContactParity, LowCameraAndLocalLightsAgreeEverywhere)
{
    PENUMBRA_EXPECT_PARITY(lowCameraContactRuns(), parity::Options{});
}

} // namespace
} // namespace penumbra
