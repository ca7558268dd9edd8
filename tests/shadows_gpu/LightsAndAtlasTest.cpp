#include "GpuTesting.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/scene/TestScenes.hpp"

#include <algorithm>
#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

class LightsAndAtlasTest : public GpuTest {};

render::FrameDesc smallFrame()
{
    render::FrameDesc frame;
    frame.width = 320;
    frame.height = 180;
    return frame;
}

bool mentions(const std::vector<std::string>& notes, const std::string& text)
{
    return std::any_of(notes.begin(), notes.end(), [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

// Share of pixels whose RGB differs by more than `tolerance` in some channel.
double differingShare(const rhi::Image& a, const rhi::Image& b, int tolerance)
{
    std::size_t differing = 0;
    for (std::size_t p = 0; p < a.bytes.size(); p += 4)
        for (std::size_t c = 0; c < 3; ++c)
            if (std::abs(int(a.bytes[p + c]) - int(b.bytes[p + c])) > tolerance) {
                ++differing;
                break;
            }
    return double(differing) / double(a.bytes.size() / 4);
}

TEST_F(LightsAndAtlasTest, LightsBeyondTheLimitAndWithoutStrengthAreLitWithoutShadowsAndReported)
{
    scene::Scene scene = scene::makeShadowTestScene();
    scene.lights[1].shadowStrength = 0.0f;
    for (int extra = 0; extra < 6; ++extra) { // 10 lights: 8 drawn, 2 beyond the lit pass's limit
        scene::DirectionalLight light = scene.lights[0];
        light.name = "extra " + std::to_string(extra);
        light.intensity = 0.05f;
        scene.lights.push_back(light);
    }
    render::SceneRenderer renderer(*device, scene);
    renderer.render(scene.camera, smallFrame());
    const shadows::DirectionalShadowPlan& plan = renderer.plan();
    ASSERT_EQ(plan.lights.size(), 4u) << "four shadow slots, filled by the first lights that can cast";
    EXPECT_EQ(plan.shadowSlots[1], -1);
    EXPECT_TRUE(mentions(renderer.notes(), "light 1 ('" + scene.lights[1].name + "') has no shadows: shadow strength is 0"));
    EXPECT_TRUE(mentions(renderer.notes(), "beyond the limit of 4 shadowed directional lights"));
    EXPECT_TRUE(mentions(renderer.notes(), "light 9 ('extra 5') is not drawn: beyond the limit of 8"));
}

TEST_F(LightsAndAtlasTest, SixteenBitAndTwentyFourBitAtlasesShadowLikeThirtyTwoBitFloat)
{
    const scene::Scene scene = scene::makeSingleLightScene();
    render::SceneRenderer renderer(*device, scene);
    render::FrameDesc frame = smallFrame();
    renderer.render(scene.camera, frame);
    const rhi::Image reference = rhi::readTexture(*device, renderer.litImage());
    for (rhi::Format format : {rhi::Format::D16, rhi::Format::D24S8}) {
        frame.shadows.directional.atlasFormat = format;
        renderer.render(scene.camera, frame);
        EXPECT_EQ(renderer.atlas().format(), format);
        const double share = differingShare(reference, rhi::readTexture(*device, renderer.litImage()), 8);
        std::printf("[ atlas    ] %s: %.4f%% of pixels differ from D32F by more than 8/255\n",
                    std::string(rhi::formatName(format)).c_str(), 100.0 * share);
        // Only shadow-edge pixels may move: a 16-bit depth step over a cascade's depth range is far below a texel's bias.
        EXPECT_LT(share, 0.005) << rhi::formatName(format);
    }
}

TEST_F(LightsAndAtlasTest, SettingsOutOfRangeAreRejectedNamingTheField)
{
    const scene::Scene scene = scene::makeSingleLightScene();
    render::SceneRenderer renderer(*device, scene);
    render::FrameDesc frame = smallFrame();
    frame.shadows.directional.atlasSize = 300;
    try {
        renderer.render(scene.camera, frame);
        FAIL() << "an atlas of 300 texels was accepted";
    } catch (const rhi::Error& e) {
        EXPECT_NE(std::string(e.what()).find("directional.atlasSize"), std::string::npos) << e.what();
    }
}

TEST_F(LightsAndAtlasTest, ShadowsDarkenTheKeyLightsShadowAndNotReceivingKeepsItLit)
{
    scene::Scene scene = scene::makeSingleLightScene();
    render::SceneRenderer renderer(*device, scene);
    renderer.render(scene.camera, smallFrame());
    const rhi::Image shadowed = rhi::readTexture(*device, renderer.litImage());
    for (scene::Material& material : scene.materials)
        material.receiveShadows = false;
    render::SceneRenderer unshadowed(*device, scene);
    unshadowed.render(scene.camera, smallFrame());
    const double share = differingShare(shadowed, rhi::readTexture(*device, unshadowed.litImage()), 8);
    EXPECT_GT(share, 0.02) << "shadows cover part of the ground";
    EXPECT_LT(share, 0.5);
}

} // namespace
} // namespace penumbra::testing
