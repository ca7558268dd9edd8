#include "GpuTesting.hpp"
#include "LitRendering.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/truth/GroundTruth.hpp"
#include "penumbra/scenes/TestScenes.hpp"

#include <algorithm>
#include <cstdio>
#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

class LightsAndAtlasTest : public GpuTest {};

render::FrameDesc atlasFrame()
{
    render::FrameDesc frame;
    frame.width = 320;
    frame.height = 180;
    return frame;
}

bool mentions(const std::vector<std::string>& notes, const std::string& text)
{
    return std::any_of(notes.begin(), notes.end(),
                       [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

TEST_F(LightsAndAtlasTest, LightsBeyondTheLimitAndWithoutStrengthAreLitWithoutShadowsAndReported)
{
    scene::Scene scene = scenes::makeShadowTestScene();
    scene.lights[1].shadowStrength = 0.0f;
    for (int extra = 0; extra < 6; ++extra) { // 10 lights: 8 drawn, 2 beyond the lit pass's limit
        scene::DirectionalLight light = scene.lights[0];
        light.name = "extra " + std::to_string(extra);
        light.intensity = 0.05f;
        scene.lights.push_back(light);
    }
    render::SceneRenderer renderer(*device, scene);
    renderer.render(scene.camera, atlasFrame());
    const shadows::DirectionalShadowPlan& plan = renderer.plan();
    ASSERT_EQ(plan.lights.size(), 4u) << "four shadow slots, filled by the first lights that can cast";
    EXPECT_EQ(plan.shadowSlots[1], -1);
    EXPECT_TRUE(
        mentions(renderer.notes(), "light 1 ('" + scene.lights[1].name + "') has no shadows: shadow strength is 0"));
    EXPECT_TRUE(mentions(renderer.notes(), "beyond the limit of 4 shadowed directional lights"));
    EXPECT_TRUE(mentions(renderer.notes(), "light 9 ('extra 5') is not drawn: beyond the limit of 8"));
}

TEST_F(LightsAndAtlasTest, SixteenBitAndTwentyFourBitAtlasesShadowLikeThirtyTwoBitFloat)
{
    const scene::Scene scene = scenes::makeSingleLightScene();
    render::SceneRenderer renderer(*device, scene);
    render::FrameDesc frame = atlasFrame();
    renderer.render(scene.camera, frame);
    const rhi::Image reference = rhi::readTexture(*device, renderer.litImage());
    for (rhi::Format format : {rhi::Format::D16, rhi::Format::D24S8}) {
        frame.shadows.directional.atlasFormat = format;
        renderer.render(scene.camera, frame);
        EXPECT_EQ(renderer.atlas().format(), format);
        const double share = differingShare(reference, rhi::readTexture(*device, renderer.litImage()), 8);
        std::printf("[ atlas    ] %s: %.4f%% of pixels differ from D32F by more than 8/255\n",
                    std::string(rhi::formatName(format)).c_str(), 100.0 * share);
        // Only shadow-edge pixels may move: a 16-bit depth step over a cascade's depth range is far below a texel's
        // bias.
        EXPECT_LT(share, 0.005) << rhi::formatName(format);
    }
}

TEST_F(LightsAndAtlasTest, SettingsOutOfRangeAreRejectedNamingTheField)
{
    const scene::Scene scene = scenes::makeSingleLightScene();
    render::SceneRenderer renderer(*device, scene);
    render::FrameDesc frame = atlasFrame();
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
    scene::Scene scene = scenes::makeSingleLightScene();
    const rhi::Image shadowed = renderLit(*device, scene, atlasFrame());
    const rhi::Image unshadowed = renderLit(*device, withoutShadows(scene), atlasFrame());
    const double share = differingShare(shadowed, unshadowed, 8);
    EXPECT_GT(share, 0.02) << "shadows cover part of the ground";
    EXPECT_LT(share, 0.5);

    // The pillar that does not receive stands in the floating cube's shadow: it must look as it does with shadows
    // off, and darken once it receives (so the first check could fail).
    const std::uint32_t pillar = *scene.findObject("unshadowed pillar");
    const truth::RayCaster cameraRays(scene, truth::RayKind::Camera);
    const truth::CpuGBuffer gbuffer = truth::traceGBuffer(scene, cameraRays, scene.camera, 320, 180);
    scene.materials[scene.objects[pillar].material].receiveShadows = true;
    const rhi::Image receiving = renderLit(*device, scene, atlasFrame());
    std::size_t pixels = 0, changed = 0, darkened = 0;
    for (std::uint32_t y = 1; y + 1 < 180; ++y)
        for (std::uint32_t x = 1; x + 1 < 320; ++x) {
            // Inside the pillar's silhouette, where rasteriser and ray cast agree on what the pixel shows.
            bool inside = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    inside = inside && gbuffer.at(x + dx, y + dy).object == pillar;
            if (!inside)
                continue;
            ++pixels;
            changed += pixel(shadowed, x, y) != pixel(unshadowed, x, y);
            darkened += luminance(receiving, x, y) < 0.5f * luminance(unshadowed, x, y);
        }
    std::printf("[ receive  ] %s: pillar %zu pixels, %zu changed by shadows, %zu darkened once it receives\n",
                configuration().c_str(), pixels, changed, darkened);
    ASSERT_GT(pixels, 30u) << "the pillar must be in view";
    EXPECT_EQ(changed, 0u) << "a material that does not receive shadows was shadowed";
    EXPECT_GT(darkened, pixels / 10) << "the pillar must stand in a shadow for this check to mean anything";
}

} // namespace
} // namespace penumbra::testing
