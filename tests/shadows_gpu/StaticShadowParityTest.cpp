// Static shadow maps across configurations, once for all of them: a bake made on each configuration loads on every
// configuration and gives the picture that configuration draws with static maps of its own.
#include "GpuTesting.hpp"
#include "StaticShadowScenes.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/shadows/StaticShadowBake.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace penumbra::testing {
namespace {

TEST(StaticShadowParity, ABakeFromEachConfigurationLoadsOnEveryConfigurationWithTheSameShadows)
{
    const scene::Scene scene = boxesUnderASpot();
    const render::FrameDesc frame = staticMapsFrame();
    std::map<std::string, shadows::StaticShadowBake> bakes;
    reportSkipped(forEachConfiguration([&](rhi::Device& device, const std::string& configuration) {
        render::SceneRenderer baker(device, scene);
        baker.render(scene.camera, frame);
        bakes.emplace(configuration, baker.bakeStaticShadows(configuration));
        ASSERT_EQ(bakes.at(configuration).maps.size(), 2u) << configuration;
    }));
    ASSERT_FALSE(bakes.empty());
    // One renderer per configuration draws its own static maps, then restores each bake in turn.
    reportSkipped(forEachConfiguration([&](rhi::Device& device, const std::string& loader) {
        render::SceneRenderer renderer(device, scene);
        renderer.render(scene.camera, frame);
        const rhi::Image live = rhi::readTexture(device, renderer.litImage());
        for (const auto& [baker, bake] : bakes) {
            SCOPED_TRACE("baked on " + baker + ", loaded on " + loader);
            renderer.useBakedShadows(bake);
            const render::FrameStats stats = renderer.render(scene.camera, frame);
            EXPECT_EQ(stats.staticCasterDraws, 0u) << "a bake draws no static caster";
            EXPECT_EQ(stats.staticMapUpdates.size(), 2u);
            const rhi::Image loaded = rhi::readTexture(device, renderer.litImage());
            EXPECT_LE(differingShare(live, loaded, 1), 0.001)
                << savePicture(live, "static-parity-live-" + loader) << " vs "
                << savePicture(loaded, "static-parity-" + baker + "-on-" + loader);
        }
    }));
}

} // namespace
} // namespace penumbra::testing
