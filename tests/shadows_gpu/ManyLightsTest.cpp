// Every spot and point light is drawn, whatever their number (issue 40): 300 small lights over a ground, each
// pool of light brighter than the same pixel without the scene's local lights, and a sample of lights removed one by
// one darkening their pool alone; with and without the depth prepass, with MSAA, with the screen-space path and with
// each filter family. The negative control brings the old limit back (the first 16 lights alone) and is caught.
#include "GpuTesting.hpp"
#include "LitRendering.hpp"
#include "ManyLightsScene.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scene/LocalLights.hpp"

#include <algorithm>
#include <array>
#include <gtest/gtest.h>
#include <set>

namespace penumbra::testing {
namespace {

constexpr std::uint32_t kManyLightsWidth = 320;
constexpr std::uint32_t kManyLightsHeight = 180;
// sRGB levels a pool stands above the ambient-lit ground (measured: 90 to 200 at its centre).
constexpr float kPoolMargin = 30.0f;
// Lights removed one at a time (local indices: spot lights 0..149, then point lights).
constexpr std::array<std::uint32_t, 4> kRemoved{0, 77, 150, 299};

struct LightsVariant {
    const char* name;
    bool prepass = true;
    std::uint32_t msaa = 1;
    render::ShadowPath path = render::ShadowPath::Forward;
    shadows::ShadowFilter filter = shadows::ShadowFilter::PCF2x2;
};

constexpr std::array kVariants{
    LightsVariant{"prepass, PCF 2x2"},
    LightsVariant{"no prepass, 4x MSAA, PCF 5x5", false, 4, render::ShadowPath::Forward, shadows::ShadowFilter::PCF5x5},
    LightsVariant{"screen-space, PCSS", true, 1, render::ShadowPath::ScreenSpace, shadows::ShadowFilter::PCSS},
};

render::FrameDesc lightsFrameOf(const LightsVariant& v)
{
    render::FrameDesc frame = litFrame(kManyLightsWidth, kManyLightsHeight, v.prepass, v.msaa);
    frame.shadowPath = v.path;
    frame.shadows.directional.atlasSize = 512;
    frame.shadows.local.atlasSize = 512;
    frame.shadows.local.filter = v.filter;
    frame.shadows.directional.filter = v.filter;
    return frame;
}

class ManyLightsTest : public GpuTest {
protected:
    // The lights (of `lights`, local indices) whose pool in `lit` is not kPoolMargin brighter than in `dark`.
    std::vector<std::uint32_t> missingPools(const ManyLightsScene& many, const rhi::Image& lit, const rhi::Image& dark,
                                            std::uint32_t lights) const
    {
        std::vector<std::uint32_t> missing;
        for (std::uint32_t i = 0; i < lights; ++i) {
            const glm::uvec2 p = pixelOf(*device, many.scene.camera, lit.width, lit.height, many.groundPoints[i]);
            if (luminance(lit, p.x, p.y) < luminance(dark, p.x, p.y) + kPoolMargin)
                missing.push_back(i);
        }
        return missing;
    }

    // The scene as drawn, then without the lights of kRemoved, then without any local light.
    struct Pictures {
        rhi::Image all;
        rhi::Image removed;
        rhi::Image dark;
    };
    Pictures render(const ManyLightsScene& many, const render::FrameDesc& frame) const
    {
        scene::Scene scene = many.scene;
        render::SceneRenderer renderer(*device, scene);
        Pictures pictures;
        renderer.render(scene.camera, frame);
        pictures.all = rhi::readTexture(*device, renderer.litImage());
        // Back to front, so that the indices still to remove stay put.
        const std::uint32_t spots = static_cast<std::uint32_t>(scene.spotLights.size());
        for (auto i = kRemoved.rbegin(); i != kRemoved.rend(); ++i) {
            if (*i < spots)
                scene.spotLights.erase(scene.spotLights.begin() + *i);
            else
                scene.pointLights.erase(scene.pointLights.begin() + (*i - spots));
        }
        renderer.render(scene.camera, frame);
        pictures.removed = rhi::readTexture(*device, renderer.litImage());
        scene.spotLights.clear();
        scene.pointLights.clear();
        renderer.render(scene.camera, frame);
        pictures.dark = rhi::readTexture(*device, renderer.litImage());
        return pictures;
    }
};

TEST_F(ManyLightsTest, EveryLightsPoolIsLitAndEachRemovedLightTakesItsPoolAway)
{
    const ManyLightsScene many = manyLightsScene();
    const auto lights = static_cast<std::uint32_t>(many.groundPoints.size());
    ASSERT_EQ(lights, kManyLightsColumns * kManyLightsRows);
    for (std::size_t v = 0; v < kVariants.size(); ++v) {
        SCOPED_TRACE(kVariants[v].name);
        const Pictures pictures = render(many, lightsFrameOf(kVariants[v]));
        const std::string saved = savePicture(pictures.all, "many-lights-" + std::to_string(v));
        EXPECT_EQ(missingPools(many, pictures.all, pictures.dark, lights), std::vector<std::uint32_t>{}) << saved;
        const std::set<std::uint32_t> removed(kRemoved.begin(), kRemoved.end());
        for (std::uint32_t i = 0; i < lights; ++i) {
            const glm::uvec2 p =
                pixelOf(*device, many.scene.camera, kManyLightsWidth, kManyLightsHeight, many.groundPoints[i]);
            const float all = luminance(pictures.all, p.x, p.y);
            const float without = luminance(pictures.removed, p.x, p.y);
            if (removed.contains(i))
                EXPECT_GT(all, without + kPoolMargin) << "light " << i << " removed: its pool stays lit; " << saved;
            else
                EXPECT_EQ(all, without) << "light " << i << " changed where another light was removed; " << saved;
        }
    }
}

// The floor: 1 024 local lights in one frame, each pool lit.
TEST_F(ManyLightsTest, ThousandAndTwentyFourLightsAreAllDrawn)
{
    const ManyLightsScene many = manyLightsScene(32, 32);
    const auto lights = static_cast<std::uint32_t>(many.groundPoints.size());
    ASSERT_EQ(lights, 1024u);
    render::FrameDesc frame = lightsFrameOf(kVariants.front());
    frame.width = 480;
    frame.height = 480;
    const rhi::Image lit = renderLit(*device, many.scene, frame);
    scene::Scene none = many.scene;
    none.spotLights.clear();
    none.pointLights.clear();
    const std::string saved = savePicture(lit, "many-lights-1024");
    EXPECT_EQ(missingPools(many, lit, renderLit(*device, none, frame), lights), std::vector<std::uint32_t>{}) << saved;
}

// A spot cone of almost a half-space (outer angle 1.55 rad, just below the pi / 2 the scene allows) is listed in
// every cluster it reaches: a ground point 68 degrees off its axis is lit.
TEST_F(ManyLightsTest, WideSpotConeLightsItsWholeReach)
{
    ManyLightsScene many = manyLightsScene(2, 1);
    scene::SpotLight& wide = many.scene.spotLights.at(0);
    wide.outerAngle = 1.55f;
    wide.innerAngle = 1.4f;
    wide.range = 4.0f;
    wide.intensity = 40.0f; // 2.7 m away and 68 degrees off the ground normal: little light arrives
    many.scene.pointLights.clear();
    const glm::vec3 offAxis = wide.position + glm::vec3(2.5f, -1.0f, 0.0f);
    const render::FrameDesc frame = lightsFrameOf(kVariants.front());
    const rhi::Image lit = renderLit(*device, many.scene, frame);
    scene::Scene none = many.scene;
    none.spotLights.clear();
    const rhi::Image dark = renderLit(*device, none, frame);
    const glm::uvec2 p = pixelOf(*device, many.scene.camera, kManyLightsWidth, kManyLightsHeight, offAxis);
    EXPECT_GT(luminance(lit, p.x, p.y), luminance(dark, p.x, p.y) + kPoolMargin)
        << savePicture(lit, "many-lights-wide");
}

// The limit back: only the first 16 local lights drawn (the scene cut to them) leaves every other pool dark, which
// the check above reports light by light.
TEST_F(ManyLightsTest, OnlyTheFirstSixteenLightsCatchesFault)
{
    const ManyLightsScene many = manyLightsScene();
    ManyLightsScene limited = many;
    scene::keepFirstLocalLights(limited.scene, 16);
    const render::FrameDesc frame = lightsFrameOf(kVariants.front());
    const rhi::Image lit = renderLit(*device, limited.scene, frame);
    scene::Scene none = many.scene;
    none.spotLights.clear();
    none.pointLights.clear();
    const rhi::Image dark = renderLit(*device, none, frame);
    const auto lights = static_cast<std::uint32_t>(many.groundPoints.size());
    const std::vector<std::uint32_t> missing = missingPools(many, lit, dark, lights);
    EXPECT_EQ(missing.size(), lights - 16);
    EXPECT_TRUE(std::none_of(missing.begin(), missing.end(), [](std::uint32_t i) { return i < 16; }));
}

} // namespace
} // namespace penumbra::testing
