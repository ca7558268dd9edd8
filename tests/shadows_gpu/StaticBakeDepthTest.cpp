// A bake's depth on this configuration (StaticShadowParity checks every pair of configurations, in one process): the
// bake holds light-space depth, what rhi::Conventions::viewDepth reads from the static atlases' texels whatever the
// depth range and direction; restored here it gives back those texels; and a bake made under each other convention
// (reversed-Z or not, depth from zero or from minus one) restores the same light-space depth, the same texels and the
// same picture.
#include "GpuTesting.hpp"
#include "StaticShadowScenes.hpp"

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/shadows/StaticShadowBake.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace penumbra::testing {
namespace {

// Light-space depth agrees within this share of the tile's depth range (float rounding of the window depth, most
// of it where a perspective depth buffer is coarse); restored window depth within this much (measured: 9e-8 at most).
constexpr float kLinearTolerance = 1e-4f;
constexpr float kWindowTolerance = 1e-6f;

// A tile's view depths at its near and far window depth: the range its projection maps, whatever the convention.
struct DepthRange {
    float nearPlane = 0.0f;
    float farPlane = 0.0f;
};

DepthRange rangeOf(const glm::mat4& projection, const rhi::Conventions& conventions)
{
    return {conventions.viewDepth(projection, conventions.nearDepth()),
            conventions.viewDepth(projection, conventions.farDepth())};
}

// The tile's projection under `other`: the same view depths onto that convention's window depth.
glm::mat4 projectionUnder(const shadows::StaticShadowTile& tile, const rhi::Conventions& conventions,
                          const rhi::Conventions& other)
{
    const DepthRange r = rangeOf(tile.projection, conventions);
    const float e = tile.frustum.extent;
    return tile.frustum.perspective ? other.perspective(e, 1.0f, r.nearPlane, r.farPlane)
                                    : other.orthographic(-e, e, -e, e, r.nearPlane, r.farPlane);
}

struct StaticAtlases {
    rhi::DepthImage directional, local;
    const rhi::DepthImage& of(const shadows::StaticShadowMap& map) const
    {
        return map.kind == shadows::LightKind::Directional ? directional : local;
    }
};

const shadows::ShadowAtlasLayout& layoutOf(const shadows::StaticShadowPlan& plan, const shadows::StaticShadowMap& map)
{
    return map.kind == shadows::LightKind::Directional ? plan.directionalAtlas : plan.localAtlas;
}

// Calls f(tile index, baked index, texel's x and y in the atlas) for every texel of the map's tiles, in the bake's
// order.
template <typename F>
void forEachTexel(const shadows::StaticShadowMap& map, const shadows::ShadowAtlasLayout& layout, F f)
{
    std::size_t i = 0;
    for (std::size_t t = 0; t < map.tiles.size(); ++t) {
        const glm::uvec2 offset = layout.tileOffset(map.tiles[t].tile);
        for (std::uint32_t y = 0; y < layout.tileSize(); ++y)
            for (std::uint32_t x = 0; x < layout.tileSize(); ++x)
                f(t, i++, offset.x + x, offset.y + y);
    }
}

// Texels of `baked` whose light-space depth is not what this convention reads from the atlas texel.
std::size_t wrongLightSpaceDepths(const shadows::BakedShadowMap& baked, const shadows::StaticShadowMap& map,
                                  const shadows::ShadowAtlasLayout& layout, const rhi::DepthImage& atlas,
                                  const rhi::Conventions& conventions)
{
    std::size_t wrong = 0;
    forEachTexel(map, layout, [&](std::size_t t, std::size_t i, std::uint32_t x, std::uint32_t y) {
        const glm::mat4& projection = map.tiles[t].projection;
        const DepthRange r = rangeOf(projection, conventions);
        const float expected = conventions.viewDepth(projection, atlas.at(x, y));
        wrong += std::abs(baked.depth.at(i) - expected) > kLinearTolerance * (r.farPlane - r.nearPlane) ? 1 : 0;
    });
    return wrong;
}

// The map as `other` would have drawn and baked it: this atlas's light-space depth written as that convention's
// window depth through its projection, then baked under it.
shadows::BakedShadowMap bakedUnder(const shadows::BakedShadowMap& own, const shadows::StaticShadowMap& map,
                                   const shadows::ShadowAtlasLayout& layout, const rhi::DepthImage& atlas,
                                   const rhi::Conventions& conventions, const rhi::Conventions& other)
{
    shadows::StaticShadowMap otherMap = map;
    for (shadows::StaticShadowTile& tile : otherMap.tiles)
        tile.projection = projectionUnder(tile, conventions, other);
    rhi::DepthImage otherAtlas{atlas.width, atlas.height, std::vector<float>(atlas.depth.size(), other.farDepth())};
    forEachTexel(map, layout, [&](std::size_t t, std::size_t, std::uint32_t x, std::uint32_t y) {
        const std::size_t at = std::size_t(y) * atlas.width + x;
        const float lightSpace = conventions.viewDepth(map.tiles[t].projection, atlas.depth[at]);
        otherAtlas.depth[at] = other.windowDepth(otherMap.tiles[t].projection, lightSpace);
    });
    shadows::BakedShadowMap baked = shadows::bakeShadowMap(otherMap, layout, otherAtlas, other);
    baked.lightName = own.lightName;
    baked.hash = own.hash;
    return baked;
}

float largestDifference(const rhi::DepthImage& a, const rhi::DepthImage& b)
{
    float largest = 0.0f;
    for (std::size_t i = 0; i < a.depth.size(); ++i)
        largest = std::max(largest, std::abs(a.depth[i] - b.depth[i]));
    return largest;
}

class StaticBakeDepthTest : public GpuTest {
protected:
    StaticAtlases read(const render::SceneRenderer& renderer)
    {
        return {rhi::readDepth(*device, renderer.staticDirectionalAtlas().texture()),
                rhi::readDepth(*device, renderer.staticLocalAtlas().texture())};
    }

    // Restores `bake` into the renderer that drew `live` and checks its static atlases and picture against it.
    void expectRestores(render::SceneRenderer& renderer, const scene::Scene& scene,
                        const shadows::StaticShadowBake& bake, const StaticAtlases& live, const rhi::Image& liveLit,
                        const std::string& name)
    {
        renderer.useBakedShadows(bake);
        renderer.render(scene.camera, staticMapsFrame());
        const StaticAtlases restored = read(renderer);
        const float directional = largestDifference(restored.directional, live.directional);
        const float local = largestDifference(restored.local, live.local);
        std::printf("[ bake     ] %s %s: restored window depth within %.2g (directional), %.2g (local)\n",
                    configuration().c_str(), name.c_str(), directional, local);
        EXPECT_LE(directional, kWindowTolerance) << name;
        EXPECT_LE(local, kWindowTolerance) << name;
        const rhi::Image lit = rhi::readTexture(*device, renderer.litImage());
        EXPECT_LE(differingShare(liveLit, lit, 1), 0.001)
            << name << ": " << savePicture(lit, "static-bake-" + name + "-" + configuration());
    }
};

TEST_F(StaticBakeDepthTest, ABakeHoldsLightSpaceDepthAndRestoresUnderEveryConvention)
{
    const scene::Scene scene = boxesUnderASpot();
    render::SceneRenderer renderer(*device, scene);
    renderer.render(scene.camera, staticMapsFrame());
    const StaticAtlases live = read(renderer);
    const rhi::Image liveLit = rhi::readTexture(*device, renderer.litImage());
    const shadows::StaticShadowPlan plan = renderer.staticPlan();
    const shadows::StaticShadowBake bake = renderer.bakeStaticShadows(configuration());
    ASSERT_EQ(bake.maps.size(), 2u);
    const rhi::Conventions& conventions = device->conventions();
    for (std::size_t m = 0; m < bake.maps.size(); ++m)
        EXPECT_EQ(wrongLightSpaceDepths(bake.maps[m], plan.maps[m], layoutOf(plan, plan.maps[m]), live.of(plan.maps[m]),
                                        conventions),
                  0u)
            << bake.maps[m].lightName;
    expectRestores(renderer, scene, bake, live, liveLit, "own");

    for (const rhi::DepthRange range : {rhi::DepthRange::ZeroToOne, rhi::DepthRange::MinusOneToOne})
        for (const bool reversed : {false, true}) {
            const rhi::Conventions other(range, reversed);
            if (range == conventions.depthRange() && reversed == conventions.reversedZ())
                continue;
            const std::string name = std::string(range == rhi::DepthRange::ZeroToOne ? "zero-to-one" : "minus-one") +
                                     (reversed ? "-reversed" : "");
            shadows::StaticShadowBake otherBake = bake;
            for (std::size_t m = 0; m < bake.maps.size(); ++m) {
                const shadows::StaticShadowMap& map = plan.maps[m];
                otherBake.maps[m] =
                    bakedUnder(bake.maps[m], map, layoutOf(plan, map), live.of(map), conventions, other);
                EXPECT_EQ(wrongLightSpaceDepths(otherBake.maps[m], map, layoutOf(plan, map), live.of(map), conventions),
                          0u)
                    << "baked " << name << ": " << bake.maps[m].lightName;
            }
            expectRestores(renderer, scene, otherBake, live, liveLit, name);
        }
}

// Two faults of a bake's depth handling, which a bake restored where it was made would not show (the restore undoes
// them): the atlas's window depth kept as it is, and window depth read under the other depth range (0..1 taken for
// -1..1 or the reverse). The check above must refuse many texels of both maps (measured on lavapipe: every texel
// with the window depth kept; under the other range 45% of the directional map, whose far texels read alike, and all
// of the spot's).
TEST_F(StaticBakeDepthTest, BakeWithoutTheConventionsDepthCatchesFault)
{
    const scene::Scene scene = boxesUnderASpot();
    render::SceneRenderer renderer(*device, scene);
    renderer.render(scene.camera, staticMapsFrame());
    const StaticAtlases live = read(renderer);
    const shadows::StaticShadowPlan& plan = renderer.staticPlan();
    const rhi::Conventions& conventions = device->conventions();
    const rhi::Conventions otherRange(conventions.depthRange() == rhi::DepthRange::ZeroToOne
                                          ? rhi::DepthRange::MinusOneToOne
                                          : rhi::DepthRange::ZeroToOne,
                                      conventions.reversedZ());
    for (const shadows::StaticShadowMap& map : plan.maps) {
        const shadows::ShadowAtlasLayout& layout = layoutOf(plan, map);
        shadows::BakedShadowMap windowDepth = shadows::bakeShadowMap(map, layout, live.of(map), conventions);
        forEachTexel(map, layout, [&](std::size_t, std::size_t i, std::uint32_t x, std::uint32_t y) {
            windowDepth.depth[i] = live.of(map).at(x, y);
        });
        const shadows::BakedShadowMap wrongRange = shadows::bakeShadowMap(map, layout, live.of(map), otherRange);
        const std::size_t texels = windowDepth.depth.size();
        const std::size_t keptAsIs = wrongLightSpaceDepths(windowDepth, map, layout, live.of(map), conventions);
        const std::size_t misread = wrongLightSpaceDepths(wrongRange, map, layout, live.of(map), conventions);
        std::printf("[ bake     ] %s map of %zu texels: %zu refused with window depth kept, %zu read under the other "
                    "range\n",
                    std::string(shadows::bakedKindName(map.kind)).c_str(), texels, keptAsIs, misread);
        EXPECT_GT(keptAsIs, texels / 2);
        EXPECT_GT(misread, texels / 4);
    }
}

} // namespace
} // namespace penumbra::testing
