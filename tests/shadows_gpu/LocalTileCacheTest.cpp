// Spot and point shadows cached per light (render/src/cache/LocalTileCache): a frame draws again only the tiles of
// the lights whose view or casters changed, says which and why, and gives the picture and the local atlas that a
// renderer drawing every tile from scratch gives, byte for byte.
#include "GpuTesting.hpp"
#include "StaticShadowScenes.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/MeshGenerators.hpp"

#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace penumbra::testing {
namespace {

// Ground, box "a" under spot "left", box "b" under spot "right", and a point light "corner" that reaches the
// ground alone: moving "a" touches the left spot's tile only.
scene::Scene twoSpotsAndABulb()
{
    scene::Scene s;
    const std::uint32_t grey = s.addMaterial({.name = "grey", .baseColor = {0.7f, 0.7f, 0.7f, 1.0f}});
    s.addObject("ground", s.addMesh(scene::makeBox({12.0f, 0.1f, 12.0f})), grey,
                glm::translate(glm::mat4(1.0f), {0.0f, -0.1f, 0.0f}));
    const std::uint32_t box = s.addMesh(scene::makeBox({0.5f, 0.5f, 0.5f}));
    s.addObject("a", box, grey, glm::translate(glm::mat4(1.0f), {-4.0f, 0.5f, 0.0f}));
    s.addObject("b", box, grey, glm::translate(glm::mat4(1.0f), {4.0f, 0.5f, 0.0f}));
    const auto spot = [](const char* name, float x) {
        return scene::SpotLight{.name = name,
                                .intensity = 40.0f,
                                .position = {x, 4.0f, 0.3f},
                                .direction = {0.0f, -1.0f, 0.0f},
                                .range = 7.0f,
                                .innerAngle = 0.35f,
                                .outerAngle = 0.45f};
    };
    s.spotLights = {spot("left", -4.0f), spot("right", 4.0f)};
    s.pointLights = {{.name = "corner", .intensity = 6.0f, .position = {0.0f, 2.0f, 7.0f}, .range = 4.0f}};
    s.camera = scene::lookAt({0.0f, 8.0f, 10.0f}, {0.0f, 0.0f, 0.0f}, 0.9f);
    return s;
}

struct DrawnTiles {
    render::FrameStats stats;
    rhi::Image lit;
    rhi::DepthImage localAtlas;
};

class LocalTileCacheTest : public GpuTest {
protected:
    DrawnTiles draw(render::SceneRenderer& renderer, const scene::Scene& scene)
    {
        render::FrameStats stats = renderer.render(scene.camera, frame_);
        return {std::move(stats), rhi::readTexture(*device, renderer.litImage()),
                rhi::readDepth(*device, renderer.localAtlas().texture())};
    }
    // The frame of a renderer that has drawn nothing before.
    DrawnTiles fresh(const scene::Scene& scene)
    {
        render::SceneRenderer renderer(*device, scene);
        return draw(renderer, scene);
    }
    void expectSame(const DrawnTiles& kept, const DrawnTiles& drawn, const std::string& what)
    {
        EXPECT_TRUE(kept.lit.bytes == drawn.lit.bytes)
            << what << ": " << savePicture(kept.lit, "local-cache-" + what + "-kept-" + configuration()) << " vs "
            << savePicture(drawn.lit, "local-cache-" + what + "-fresh-" + configuration());
        EXPECT_TRUE(kept.localAtlas.depth == drawn.localAtlas.depth) << what << ": the local atlases differ";
    }

    render::FrameDesc frame_ = staticMapsFrame(shadows::StaticShadowUpdate::EveryFrame);
};

constexpr std::uint32_t kTiles = 1 + 1 + 6; // two spot lights, a point light's six faces

TEST_F(LocalTileCacheTest, OnlyTheLightsWhoseViewOrCastersChangedAreDrawnAgain)
{
    scene::Scene scene = twoSpotsAndABulb();
    render::SceneRenderer renderer(*device, scene);
    const DrawnTiles first = draw(renderer, scene);
    EXPECT_EQ(first.stats.localTilesDrawn, kTiles);
    EXPECT_EQ(first.stats.localTilesCached, 0u);
    EXPECT_EQ(first.stats.localShadowUpdates, (std::vector<std::string>{"spot light 0 ('left'): its tile is new",
                                                                        "spot light 1 ('right'): its tile is new",
                                                                        "point light 0 ('corner'): its tile is new"}));
    EXPECT_EQ(first.stats.shadowedLights, 3u);
    EXPECT_EQ(first.stats.lightsWithoutShadow, 0u);

    const DrawnTiles still = draw(renderer, scene);
    EXPECT_EQ(still.stats.localTilesDrawn, 0u);
    EXPECT_EQ(still.stats.localTilesCached, kTiles);
    EXPECT_EQ(still.stats.localCasterDraws, 0u);
    EXPECT_TRUE(still.stats.localShadowUpdates.empty());
    expectSame(still, first, "still");

    moveObject(scene, "a", {0.3f, 0.0f, 0.2f});
    const DrawnTiles moved = draw(renderer, scene);
    EXPECT_EQ(moved.stats.localShadowUpdates,
              std::vector<std::string>{"spot light 0 ('left'): a caster in its view changed"});
    EXPECT_EQ(moved.stats.localTilesDrawn, 1u);
    EXPECT_EQ(moved.stats.localTilesCached, kTiles - 1);
    expectSame(moved, fresh(scene), "moved");

    scene.spotLights[1].range = 6.5f;
    const DrawnTiles reached = draw(renderer, scene);
    EXPECT_EQ(reached.stats.localShadowUpdates, std::vector<std::string>{"spot light 1 ('right'): its view changed"});
    expectSame(reached, fresh(scene), "range");
}

// The comparison above tells a stale tile from a fresh one: after "a" moves, a frame whose left spot kept its old tile
// (stood for by "a" casting nothing and a shadow-only copy at its old place) differs from the frame drawn afresh.
TEST_F(LocalTileCacheTest, StaleTileCatchesFault)
{
    scene::Scene scene = twoSpotsAndABulb();
    const scene::Object old = scene.objects.at(scene.findObject("a").value());
    moveObject(scene, "a", {0.3f, 0.0f, 0.2f});
    const DrawnTiles drawn = fresh(scene);
    scene::Scene stale = scene;
    stale.objects.at(stale.findObject("a").value()).castShadows = scene::ShadowCasting::Off;
    const std::uint32_t ghost = stale.addObject("a as cached", old.mesh, old.material, old.transform);
    stale.objects[ghost].castShadows = scene::ShadowCasting::ShadowsOnly;
    const DrawnTiles kept = fresh(stale);
    EXPECT_FALSE(kept.lit.bytes == drawn.lit.bytes);
    EXPECT_FALSE(kept.localAtlas.depth == drawn.localAtlas.depth);
}

} // namespace
} // namespace penumbra::testing
