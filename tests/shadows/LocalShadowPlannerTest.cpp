// Spot and point shadow planning: matrices, cube faces, tile bounds, the FOV bias and the tile budget.
#include "ShadowTestSupport.hpp"

#include "penumbra/shadows/LocalLightProjection.hpp"
#include "penumbra/shadows/LocalShadowPlanner.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

using testing::allConventions;
using testing::conventionName;

// (u, v, window depth) of a world point in tile `tile`, u and v over the tile.
glm::vec3 atlasPosition(const LocalShadowPlan& plan, std::uint32_t tile, glm::vec3 world)
{
    const glm::vec4 p = plan.uniforms.worldToAtlas[tile] * glm::vec4(world, 1.0f);
    const glm::vec2 uv =
        glm::vec2(p) / p.w * static_cast<float>(plan.atlas.split()) - glm::vec2(plan.atlas.tileCoordinates(tile));
    return {uv, p.z / p.w};
}

TEST(CubeFace, PicksTheLargestComponentWithTiesToXThenY)
{
    EXPECT_EQ(cubeFace({1, 0.2f, -0.3f}), CubeFace::PositiveX);
    EXPECT_EQ(cubeFace({-1, 0.99f, 0.99f}), CubeFace::NegativeX);
    EXPECT_EQ(cubeFace({0.1f, 2, -1}), CubeFace::PositiveY);
    EXPECT_EQ(cubeFace({0.1f, -2, 1.9f}), CubeFace::NegativeY);
    EXPECT_EQ(cubeFace({0.1f, 0.3f, 0.5f}), CubeFace::PositiveZ);
    EXPECT_EQ(cubeFace({0.0f, 0.0f, -1.0f}), CubeFace::NegativeZ);
    // On the boundaries.
    EXPECT_EQ(cubeFace({1, 1, 0}), CubeFace::PositiveX);
    EXPECT_EQ(cubeFace({-1, 0, 1}), CubeFace::NegativeX);
    EXPECT_EQ(cubeFace({0, -1, -1}), CubeFace::NegativeY);
    EXPECT_EQ(cubeFace({1, 1, 1}), CubeFace::PositiveX);
    // Just off a boundary, either side.
    EXPECT_EQ(cubeFace({1.0f, 1.0001f, 0.0f}), CubeFace::PositiveY);
    EXPECT_EQ(cubeFace({1.0001f, 1.0f, 0.0f}), CubeFace::PositiveX);
    EXPECT_EQ(cubeFace({0.0f, 0.9999f, -1.0f}), CubeFace::NegativeZ);
    for (std::uint32_t f = 0; f < cubeFaceCount; ++f)
        EXPECT_EQ(cubeFace(cubeFaceAxis(static_cast<CubeFace>(f))), static_cast<CubeFace>(f));
}

TEST(PointFaceView, LooksAlongTheAxisUnmirrored)
{
    const glm::vec3 light{1, 2, 3};
    for (std::uint32_t f = 0; f < cubeFaceCount; ++f) {
        const glm::mat4 view = pointFaceView(static_cast<CubeFace>(f), light);
        const glm::vec3 ahead = glm::vec3(view * glm::vec4(light + 2.0f * cubeFaceAxis(static_cast<CubeFace>(f)), 1));
        EXPECT_NEAR(ahead.x, 0.0f, 1e-5f) << f;
        EXPECT_NEAR(ahead.y, 0.0f, 1e-5f) << f;
        EXPECT_NEAR(ahead.z, -2.0f, 1e-5f) << f;
        // A rotation, not a reflection: front faces stay counter-clockwise.
        EXPECT_NEAR(glm::determinant(glm::mat3(view)), 1.0f, 1e-5f) << f;
    }
}

// One caster box around every light of these tests: each has something to shadow.
const std::vector<Bounds> kEverywhere{{{-100.0f, -100.0f, -100.0f}, {100.0f, 100.0f, 100.0f}}};

TEST(FovBias, MatchesTheDocumentsFormula)
{
    // atan(1 + bias + filter) x 2 - 90 degrees, texel 2 / tile, filter = texel x (filter enum + 1).
    const float texel = 2.0f / 256.0f;
    const float filter = texel * 3.0f; // PCF5x5
    const float bias = 1.5f * filter * std::sqrt(2.0f);
    const float expected = glm::degrees(std::atan(1.0f + bias + filter)) * 2.0f - 90.0f;
    EXPECT_NEAR(pointFaceFovBiasDegrees(256, ShadowFilter::PCF5x5, 1.5f), expected, 1e-4f);
    EXPECT_GT(pointFaceFovBiasDegrees(256, ShadowFilter::PCF2x2, 0.0f), 0.0f);
    EXPECT_LT(pointFaceFovBiasDegrees(1024, ShadowFilter::PCF2x2, 1.0f),
              pointFaceFovBiasDegrees(256, ShadowFilter::PCF2x2, 1.0f));
    EXPECT_NEAR(glm::degrees(pointFaceFieldOfView(256, ShadowFilter::PCF5x5, 1.5f)), 90.0f + expected, 1e-4f);
}

TEST(SpotShadow, AxisHitsTheTileCentreAndTheConeEdgeItsBorder)
{
    for (const rhi::Conventions& conventions : allConventions()) {
        SCOPED_TRACE(conventionName(conventions));
        const SpotShadowInput spot{.position = {0, 5, 0},
                                   .direction = glm::normalize(glm::vec3(0.3f, -1, 0.2f)),
                                   .range = 20.0f,
                                   .outerAngle = glm::radians(30.0f)};
        ShadowSettings settings;
        const LocalShadowPlan plan = planLocalShadows(settings, conventions, {}, {&spot, 1}, {}, kEverywhere);
        ASSERT_EQ(plan.tiles.size(), 1u);
        const glm::vec3 onAxis = atlasPosition(plan, 0, spot.position + 7.0f * spot.direction);
        EXPECT_NEAR(onAxis.x, 0.5f, 1e-5f);
        EXPECT_NEAR(onAxis.y, 0.5f, 1e-5f);
        // The depth grows from the near towards the far value along the axis.
        const float nearer = atlasPosition(plan, 0, spot.position + 3.0f * spot.direction).z;
        EXPECT_TRUE(conventions.reversedZ() ? nearer > onAxis.z : nearer < onAxis.z);
        // A point on the cone's edge, in the light view's x direction, lands on the tile's edge.
        const glm::mat4 view = spotView(spot.position, spot.direction);
        const glm::vec3 right = glm::vec3(glm::inverse(view)[0]);
        const float distance = 5.0f;
        const glm::vec3 edge = spot.position + distance * spot.direction + distance * std::tan(spot.outerAngle) * right;
        EXPECT_NEAR(atlasPosition(plan, 0, edge).x, 1.0f, 1e-4f);
        // Normal bias: texel size at distance 1 x filter factor x sqrt 2.
        const float texel = 2.0f * std::tan(spot.outerAngle) / static_cast<float>(settings.local.atlasSize);
        EXPECT_NEAR(plan.uniforms.tiles[0].normalBias, texel * std::sqrt(2.0f), 1e-6f);
    }
}

TEST(PointShadow, EachFaceTileHoldsItsDirection)
{
    for (const rhi::Conventions& conventions : allConventions()) {
        SCOPED_TRACE(conventionName(conventions));
        const PointShadowInput point{.position = {2, 3, -1}, .range = 10.0f};
        const LocalShadowPlan plan = planLocalShadows(ShadowSettings{}, conventions, {}, {}, {&point, 1}, kEverywhere);
        ASSERT_EQ(plan.tiles.size(), 6u);
        EXPECT_EQ(plan.pointShadows[0], 0);
        for (std::uint32_t f = 0; f < cubeFaceCount; ++f) {
            const glm::vec3 axis = cubeFaceAxis(static_cast<CubeFace>(f));
            const glm::vec3 p = atlasPosition(plan, f, point.position + 4.0f * axis);
            EXPECT_NEAR(p.x, 0.5f, 1e-5f) << f;
            EXPECT_NEAR(p.y, 0.5f, 1e-5f) << f;
            // A direction on the face's boundary (45 degrees off the axis) is still inside the widened tile.
            const glm::vec3 side = cubeFaceAxis(static_cast<CubeFace>((f + 2) % cubeFaceCount));
            const glm::vec3 q = atlasPosition(plan, f, point.position + 4.0f * (axis + side));
            EXPECT_GT(q.x, 0.0f) << f;
            EXPECT_LT(q.x, 1.0f) << f;
            EXPECT_GT(q.y, 0.0f) << f;
            EXPECT_LT(q.y, 1.0f) << f;
        }
    }
}

TEST(LocalAtlas, TileBoundsAreTheTilesTexelsAndTilesAreUniformlySplit)
{
    const std::vector<SpotShadowInput> spots(5);
    ShadowSettings settings;
    settings.local.atlasSize = 512;
    const LocalShadowPlan plan = planLocalShadows(settings, allConventions()[0], {}, spots, {}, kEverywhere);
    EXPECT_EQ(plan.atlas.split(), 4u);
    EXPECT_EQ(plan.atlas.tileSize(), 128u);
    EXPECT_EQ(plan.uniforms.tileBounds[0], glm::vec4(0, 0, 127, 127));
    EXPECT_EQ(plan.uniforms.tileBounds[4], glm::vec4(0, 128, 127, 255));
    EXPECT_EQ(plan.uniforms.tileBounds[1], glm::vec4(128, 0, 255, 127));
    for (std::uint32_t t = 0; t < 5; ++t) {
        EXPECT_EQ(plan.tiles[t].tile, t);
        EXPECT_EQ(plan.tiles[t].viewport.x, plan.uniforms.tileBounds[t].x);
        EXPECT_EQ(plan.tiles[t].viewport.y, plan.uniforms.tileBounds[t].y);
    }
}

TEST(LocalAtlas, TileBudgetTakesSpotsThenPointsAndReportsWhatDoesNotFit)
{
    const std::vector<SpotShadowInput> spots(5);
    std::vector<PointShadowInput> points(3);
    points[1].strength = 0.0f;
    const LocalShadowPlan plan =
        planLocalShadows(ShadowSettings{}, allConventions()[0], {}, spots, points, kEverywhere);
    // 5 spots + 6 (point 0) = 11; point 1 casts nothing; point 2 needs 6 more, 5 are left.
    EXPECT_EQ(plan.atlas.tileCount(), 11u);
    EXPECT_EQ(plan.spotTiles, (std::vector<int>{0, 1, 2, 3, 4}));
    EXPECT_EQ(plan.pointShadows, (std::vector<int>{5, -1, -1}));
    ASSERT_EQ(plan.report.size(), 2u);
    EXPECT_EQ(plan.report[0].kind, LightKind::Point);
    EXPECT_EQ(plan.report[0].lightIndex, 1u);
    EXPECT_EQ(plan.report[0].reason, "shadow strength is 0");
    EXPECT_EQ(plan.report[1].lightIndex, 2u);
    EXPECT_EQ(plan.report[1].reason, "needs 6 of the local atlas's 16 tiles, 5 are left");

    const std::vector<SpotShadowInput> many(18);
    const LocalShadowPlan full = planLocalShadows(ShadowSettings{}, allConventions()[0], {}, many, {}, kEverywhere);
    EXPECT_EQ(full.atlas.tileCount(), 16u);
    EXPECT_EQ(full.spotTiles[16], -1);
    EXPECT_EQ(full.report.size(), 2u);
}

TEST(LocalAtlas, FrustumCullingKeepsOnlyCastersInTheCone)
{
    const SpotShadowInput spot{.position = {0, 10, 0},
                               .direction = {0, -1, 0},
                               .range = 15.0f,
                               .outerAngle = glm::radians(20.0f)};
    const std::vector<Bounds> casters{{{-1, 0, -1}, {1, 1, 1}}, // below the light
                                      {{20, 0, 20}, {21, 1, 21}}, // far outside the cone
                                      {{-1, 11, -1}, {1, 12, 1}}, // behind the light
                                      {{-1, -9, -1}, {1, -8, 1}}, // beyond the range
                                      {{3, 0, -0.5f}, {5, 1, 0.5f}}}; // reaching into the cone's edge
    const LocalShadowPlan plan = planLocalShadows(ShadowSettings{}, allConventions()[0], {}, {&spot, 1}, {}, casters);
    EXPECT_EQ(plan.tiles[0].view.casters, (std::vector<std::uint32_t>{0, 4}));
}

TEST(LocalAtlas, NearPlaneIsTheLightsOwnOrTheSettingsFractionOfItsRange)
{
    const rhi::Conventions conventions = allConventions()[0];
    ShadowSettings settings;
    settings.local.nearPlane = 0.05f;
    const std::vector<SpotShadowInput> spots{{.position = {0, 5, 0}, .range = 20.0f},
                                             {.position = {0, 5, 0}, .range = 20.0f, .nearPlane = 0.25f}};
    const LocalShadowPlan plan = planLocalShadows(settings, conventions, {}, spots, {}, kEverywhere);
    ASSERT_EQ(plan.tiles.size(), 2u);
    EXPECT_EQ(plan.tiles[0].view.projection, conventions.perspective(2.0f * spots[0].outerAngle, 1.0f, 1.0f, 20.0f));
    EXPECT_EQ(plan.tiles[1].view.projection, conventions.perspective(2.0f * spots[1].outerAngle, 1.0f, 0.25f, 20.0f));
}

TEST(LocalAtlas, LightsThatShadowNothingInViewTakeNoTile)
{
    // Spot 0 shines down on the caster; spot 1 shines up, away from it; point 0 is 30 units from it with a range
    // of 10; point 1 is beside it but 200 units ahead of the camera, beyond the shadow distance of 100.
    const std::vector<Bounds> casters{{{-1, 0, -1}, {1, 1, 1}}};
    const std::vector<SpotShadowInput> spots{{.position = {0, 5, 0}, .direction = {0, -1, 0}, .range = 10.0f},
                                             {.position = {0, 5, 0}, .direction = {0, 1, 0}, .range = 10.0f}};
    const std::vector<PointShadowInput> points{{.position = {30, 0, 0}, .range = 10.0f},
                                               {.position = {0, 2, -205}, .range = 10.0f}};
    const std::vector<Bounds> withFarCaster{casters[0], {{-1, 0, -206}, {1, 1, -204}}};
    const ShadowCamera camera; // at the origin, looking down -z
    const LocalShadowPlan plan =
        planLocalShadows(ShadowSettings{}, allConventions()[0], camera, spots, points, withFarCaster);
    EXPECT_EQ(plan.spotTiles, (std::vector<int>{0, -1}));
    EXPECT_EQ(plan.pointShadows, (std::vector<int>{-1, -1}));
    EXPECT_EQ(plan.atlas.tileCount(), 1u);
    ASSERT_EQ(plan.report.size(), 3u);
    EXPECT_EQ(plan.report[0].reason, "no shadow caster is within its reach");
    EXPECT_EQ(plan.report[1].reason, "no shadow caster is within its reach");
    EXPECT_EQ(plan.report[2].reason, "its reach begins at view depth 195, beyond the shadow distance 100");
}

} // namespace
} // namespace penumbra::shadows
