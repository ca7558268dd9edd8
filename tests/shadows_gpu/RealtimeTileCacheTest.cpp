// The realtime tiles' cache of static depth (RealtimeCasters::Dynamic, render/static/StaticTileCache): a static
// caster that moves between frames is drawn again into the tiles that see it, so the frame after the move is the one
// a renderer drawing from scratch gives, byte for byte: the lit image, both realtime atlases and both static atlases.
#include "GpuTesting.hpp"
#include "StaticShadowScenes.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/MeshGenerators.hpp"

#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <string>

namespace penumbra::testing {
namespace {

// Box "a" stands under the lamp and in the sun's view; this moves it within both.
const glm::vec3 kMove{1.2f, 0.0f, 0.9f};

struct DrawnAtlases {
    rhi::Image lit;
    rhi::DepthImage atlas, localAtlas, staticAtlas, staticLocalAtlas;
};

render::FrameDesc dynamicCastersFrame()
{
    render::FrameDesc frame = staticMapsFrame();
    frame.shadows.staticMaps.realtimeCasters = shadows::RealtimeCasters::Dynamic;
    return frame;
}

// boxesUnderASpot with a dynamic ball, so that the realtime atlases draw a caster of their own over the cached
// static depth.
scene::Scene boxesAndABall()
{
    scene::Scene s = boxesUnderASpot();
    const std::uint32_t ball = s.addObject("ball", s.addMesh(scene::makeSphere(0.4f, 16, 12)), 0,
                                           glm::translate(glm::mat4(1.0f), {-1.5f, 0.4f, 1.5f}));
    s.objects[ball].mobility = scene::Mobility::Dynamic;
    return s;
}

class RealtimeTileCacheTest : public GpuTest {
protected:
    DrawnAtlases read(const render::SceneRenderer& renderer)
    {
        return {rhi::readTexture(*device, renderer.litImage()), rhi::readDepth(*device, renderer.atlas().texture()),
                rhi::readDepth(*device, renderer.localAtlas().texture()),
                rhi::readDepth(*device, renderer.staticDirectionalAtlas().texture()),
                rhi::readDepth(*device, renderer.staticLocalAtlas().texture())};
    }

    // The scene as it is now, drawn by a renderer that has drawn nothing before.
    DrawnAtlases fresh(const scene::Scene& scene)
    {
        render::SceneRenderer renderer(*device, scene);
        renderer.render(scene.camera, dynamicCastersFrame());
        return read(renderer);
    }

    std::string pictures(const DrawnAtlases& kept, const DrawnAtlases& drawn, const std::string& name)
    {
        return savePicture(kept.lit, "tile-cache-" + name + "-kept-" + configuration()) + " vs " +
               savePicture(drawn.lit, "tile-cache-" + name + "-fresh-" + configuration());
    }
};

TEST_F(RealtimeTileCacheTest, AStaticCasterThatMovesIsDrawnAgainIntoTheCachedTiles)
{
    scene::Scene scene = boxesAndABall();
    const render::FrameDesc frame = dynamicCastersFrame();
    render::SceneRenderer renderer(*device, scene);
    renderer.render(scene.camera, frame);
    renderer.render(scene.camera, frame); // the tiles' static depth now comes from their caches
    moveObject(scene, "a", kMove);
    const render::FrameStats stats = renderer.render(scene.camera, frame);
    EXPECT_GT(stats.staticCasterDraws, 0u) << "the moved box is drawn again";
    const DrawnAtlases kept = read(renderer);
    const DrawnAtlases drawn = fresh(scene);
    EXPECT_TRUE(kept.lit.bytes == drawn.lit.bytes) << pictures(kept, drawn, "moved");
    EXPECT_TRUE(kept.atlas.depth == drawn.atlas.depth) << "the directional atlas";
    EXPECT_TRUE(kept.localAtlas.depth == drawn.localAtlas.depth) << "the local atlas";
    EXPECT_TRUE(kept.staticAtlas.depth == drawn.staticAtlas.depth) << "the static directional atlas";
    EXPECT_TRUE(kept.staticLocalAtlas.depth == drawn.staticLocalAtlas.depth) << "the static local atlas";
}

// A cache keyed by caster index alone keeps the moved box's old depth in the realtime tiles while the static maps
// draw it where it now stands: a shadow at both places. Drawn here as the same realtime depth gives it: a dynamic
// shadows-only copy of the box left at its old place, which the realtime atlases draw and the static maps do not.
// The comparison above must see the second shadow (measured: 0.38% of the pixels, 55, on lavapipe).
TEST_F(RealtimeTileCacheTest, CasterIndexKeyCatchesFault)
{
    scene::Scene scene = boxesAndABall();
    const scene::Object old = scene.objects.at(scene.findObject("a").value());
    moveObject(scene, "a", kMove);
    const DrawnAtlases drawn = fresh(scene);
    scene::Scene stale = scene;
    const std::uint32_t ghost = stale.addObject("a as cached", old.mesh, old.material, old.transform);
    stale.objects[ghost].mobility = scene::Mobility::Dynamic;
    stale.objects[ghost].castShadows = scene::ShadowCasting::ShadowsOnly;
    const DrawnAtlases kept = fresh(stale);
    const double share = differingShare(kept.lit, drawn.lit, 1);
    std::printf("[ cache    ] the old shadow left behind: %.2f%% of the pixels differ\n", 100.0 * share);
    EXPECT_GT(share, 0.002) << pictures(kept, drawn, "left-behind");
    EXPECT_FALSE(kept.atlas.depth == drawn.atlas.depth);
}

} // namespace
} // namespace penumbra::testing
