// Static shadow planning: which lights get maps, every static caster inside its map, the realtime tiles' projections
// for spot and point lights, and the uniforms in the lit pass's light order.
#include "ShadowTestSupport.hpp"

#include "penumbra/shadows/SoftShadowUniforms.hpp"
#include "penumbra/shadows/StaticShadowPlanner.hpp"

#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

using testing::allConventions;
using testing::conventionName;

ShadowSettings cachedSettings()
{
    ShadowSettings s;
    s.staticMaps.update = StaticShadowUpdate::OnChange;
    return s;
}

// Three boxes; the middle one is dynamic.
const std::vector<Bounds> kBounds{{{-20, 0, -20}, {-10, 8, -10}}, {{0, 0, 0}, {1, 1, 1}}, {{10, 0, 10}, {30, 20, 30}}};
const std::vector<std::uint32_t> kStatic{0, 2};

TEST(StaticShadowPlanner, EveryFrameModeOrNoStaticCasterPlansNoMap)
{
    const rhi::Conventions conventions{rhi::DepthRange::ZeroToOne, false};
    const std::vector<DirectionalShadowLightInput> sun{{}};
    EXPECT_TRUE(planStaticShadows(ShadowSettings{}, conventions, sun, {}, {}, {kBounds, kStatic}).maps.empty());
    EXPECT_TRUE(planStaticShadows(cachedSettings(), conventions, sun, {}, {}, {kBounds, {}}).maps.empty());
}

TEST(StaticShadowPlanner, DirectionalMapHoldsEveryStaticCasterInsideItsTile)
{
    for (const rhi::Conventions& conventions : allConventions()) {
        SCOPED_TRACE(conventionName(conventions));
        const std::vector<DirectionalShadowLightInput> lights{{.direction = {0.3f, -1.0f, 0.2f}},
                                                              {.strength = 0.0f},
                                                              {.direction = {-0.5f, -0.4f, 0.1f}}};
        const StaticShadowPlan plan =
            planStaticShadows(cachedSettings(), conventions, lights, {}, {}, {kBounds, kStatic});
        ASSERT_EQ(plan.maps.size(), 2u); // the light without strength has none
        EXPECT_EQ(plan.directionalAtlas.tileCount(), 2u);
        EXPECT_EQ(plan.uniforms.directionalLights[1].tile, -1);
        for (std::uint32_t m = 0; m < 2; ++m) {
            const StaticShadowMap& map = plan.maps[m];
            EXPECT_EQ(map.kind, LightKind::Directional);
            ASSERT_EQ(map.tiles.size(), 1u);
            EXPECT_EQ(map.tiles[0].casters, kStatic);
            const TileTexelBounds bounds = plan.uniforms.directionalBounds[map.tiles[0].tile];
            const float size = static_cast<float>(plan.directionalAtlas.atlasSize());
            for (const std::uint32_t i : kStatic)
                for (const glm::vec3& corner : kBounds[i].corners()) {
                    const glm::vec4 p =
                        plan.uniforms.directionalWorldToMap[map.tiles[0].tile] * glm::vec4(corner, 1.0f);
                    EXPECT_GE(p.x * size, static_cast<float>(bounds.first.x));
                    EXPECT_LE(p.x * size, static_cast<float>(bounds.last.x) + 1.0f);
                    EXPECT_GE(p.y * size, static_cast<float>(bounds.first.y));
                    EXPECT_LE(p.y * size, static_cast<float>(bounds.last.y) + 1.0f);
                    // Between the near and the far plane in window depth, whichever way depth runs.
                    EXPECT_GE(p.z, -1e-4f);
                    EXPECT_LE(p.z, 1.0f + 1e-4f);
                }
        }
        EXPECT_EQ(plan.uniforms.directionalLights[2].tile, static_cast<int>(plan.maps[1].tiles[0].tile));
    }
}

TEST(StaticShadowPlanner, SpotAndPointMapsTakeTilesInTheLitPassOrder)
{
    const rhi::Conventions conventions{rhi::DepthRange::ZeroToOne, true};
    const std::vector<SpotShadowInput> spots{{.position = {-15, 12, -15}, .range = 30.0f},
                                             {.position = {0, 5, 0}, .strength = 0.0f}};
    const std::vector<PointShadowInput> points{{.position = {20, 25, 20}, .range = 40.0f}};
    const StaticShadowPlan plan =
        planStaticShadows(cachedSettings(), conventions, {}, spots, points, {kBounds, kStatic});
    ASSERT_EQ(plan.maps.size(), 2u);
    EXPECT_EQ(plan.maps[0].kind, LightKind::Spot);
    EXPECT_EQ(plan.maps[0].tiles.size(), 1u);
    EXPECT_EQ(plan.maps[1].kind, LightKind::Point);
    EXPECT_EQ(plan.maps[1].tiles.size(), 6u);
    EXPECT_EQ(plan.localAtlas.tileCount(), 7u);
    // The spot light sees the first box below it, never the dynamic one's index.
    EXPECT_EQ(plan.maps[0].tiles[0].casters, std::vector<std::uint32_t>{0});
    ASSERT_EQ(plan.localLightMaps.size(), 3u);
    EXPECT_EQ(plan.localLightMaps[0].tile, 0);
    EXPECT_EQ(plan.localLightMaps[1].tile, -1); // no strength, no map
    EXPECT_EQ(plan.localLightMaps[2].tile, 1); // the point light after both spot lights
    for (const StaticShadowTile& tile : plan.maps[1].tiles)
        for (const std::uint32_t caster : tile.casters)
            EXPECT_NE(caster, 1u);
}

TEST(StaticShadowPlanner, LightsBeyondTheTileBudgetAreReported)
{
    const rhi::Conventions conventions{rhi::DepthRange::ZeroToOne, false};
    // Ten point lights fill 60 of the 64 tiles; the eleventh needs six.
    const std::vector<PointShadowInput> points(11, PointShadowInput{.position = {0, 10, 0}, .range = 50.0f});
    const StaticShadowPlan plan = planStaticShadows(cachedSettings(), conventions, {}, {}, points, {kBounds, kStatic});
    EXPECT_EQ(plan.maps.size(), 10u);
    ASSERT_EQ(plan.report.size(), 1u);
    EXPECT_EQ(plan.report[0].lightIndex, 10u);
    EXPECT_NE(plan.report[0].reason.find("no static map"), std::string::npos);
}

TEST(StaticShadowPlanner, SoftFiltersStayWithTheirSoftData)
{
    const rhi::Conventions conventions{rhi::DepthRange::ZeroToOne, false};
    const std::vector<DirectionalShadowLightInput> sun{{.filter = ShadowFilter::PCSS, .angularDiameter = 2.0f}};
    const StaticShadowPlan plan = planStaticShadows(cachedSettings(), conventions, sun, {}, {}, {kBounds, kStatic});
    EXPECT_TRUE(plan.report.empty());
    EXPECT_EQ(plan.uniforms.directionalLights[0].shadowFilter, ShadowFilter::PCSS);
    EXPECT_FLOAT_EQ(plan.uniforms.directionalSource[0].tanHalfAngle, tanHalfAngularDiameter(2.0f));
    EXPECT_FLOAT_EQ(plan.uniforms.directionalSource[0].texelWorldSize, plan.maps[0].texelSize);
    EXPECT_NE(plan.uniforms.directionalSoft[0].depthRow.x, 0.0f);
}

} // namespace
} // namespace penumbra::shadows
