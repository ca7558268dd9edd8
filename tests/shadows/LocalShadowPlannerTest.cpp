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
    const glm::vec4 p = plan.tileData[tile].worldToAtlas * glm::vec4(world, 1.0f);
    const rhi::Viewport& place = plan.tiles[tile].viewport;
    const glm::vec2 uv =
        (glm::vec2(p) / p.w * static_cast<float>(plan.atlasSize) - glm::vec2(place.x, place.y)) / place.width;
    return {uv, p.z / p.w};
}

// Whether two tiles of the plan share a texel.
bool overlap(const rhi::Viewport& a, const rhi::Viewport& b)
{
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

void expectDisjointTiles(const LocalShadowPlan& plan)
{
    for (std::size_t i = 0; i < plan.tiles.size(); ++i) {
        const rhi::Viewport& a = plan.tiles[i].viewport;
        EXPECT_LE(a.x + a.width, static_cast<float>(plan.atlasSize)) << i;
        EXPECT_LE(a.y + a.height, static_cast<float>(plan.atlasSize)) << i;
        for (std::size_t j = i + 1; j < plan.tiles.size(); ++j)
            EXPECT_FALSE(overlap(a, plan.tiles[j].viewport)) << i << " and " << j;
    }
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
        const float texel = 2.0f * std::tan(spot.outerAngle) / plan.tiles[0].viewport.width;
        EXPECT_NEAR(plan.tileData[0].normalBias, texel * std::sqrt(2.0f), 1e-6f);
    }
}

// The FOV bias of spot lights (local.spotFovBias) is the point faces' formula over the cone: off, the cone's own angle;
// on, the cone's edge lies the normal bias and the filter size inside the tile's edge, in texels of the cone's tile.
TEST(SpotShadow, FovBiasKeepsTheConeEdgeTheBiasAndFilterInsideTheTile)
{
    EXPECT_EQ(spotFieldOfView(0.6f, 256, ShadowFilter::PCF5x5, 1.5f, Toggle::Off), 1.2f);
    EXPECT_NEAR(spotFieldOfView(glm::radians(45.0f), 256, ShadowFilter::PCF5x5, 1.5f, Toggle::On),
                pointFaceFieldOfView(256, ShadowFilter::PCF5x5, 1.5f), 1e-6f);
    for (const rhi::Conventions& conventions : allConventions()) {
        SCOPED_TRACE(conventionName(conventions));
        const SpotShadowInput spot{.position = {0, 5, 0},
                                   .direction = glm::normalize(glm::vec3(0.3f, -1, 0.2f)),
                                   .range = 20.0f,
                                   .outerAngle = glm::radians(30.0f),
                                   .normalBias = 1.5f};
        ShadowSettings settings;
        settings.local.filter = ShadowFilter::PCF5x5;
        settings.local.spotFovBias = Toggle::On;
        settings.local.depthBias = 3.0f;
        const LocalShadowPlan plan = planLocalShadows(settings, conventions, {}, {&spot, 1}, {}, kEverywhere);
        ASSERT_EQ(plan.tiles.size(), 1u);
        EXPECT_EQ(plan.tiles[0].view.depthBias, 3.0f);
        const float tile = plan.tiles[0].viewport.width;
        const glm::vec3 right = glm::vec3(glm::inverse(spotView(spot.position, spot.direction))[0]);
        const float distance = 5.0f;
        const glm::vec3 edge = spot.position + distance * spot.direction + distance * std::tan(spot.outerAngle) * right;
        // Texels of the cone's own tile, 3 of them for the 5x5 filter, plus the normal bias's 1.5 sqrt 2 of those.
        const float coneTexel = 2.0f * std::tan(spot.outerAngle) / tile;
        const float widenedTexel = 2.0f *
                                   std::tan(0.5f * spotFieldOfView(spot.outerAngle, static_cast<std::uint32_t>(tile),
                                                                   ShadowFilter::PCF5x5, 1.5f, Toggle::On)) /
                                   tile;
        const float inside = 3.0f * (1.0f + 1.5f * std::sqrt(2.0f)) * coneTexel / widenedTexel;
        EXPECT_NEAR((1.0f - atlasPosition(plan, 0, edge).x) * tile, inside, 1e-2f);
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

TEST(LocalAtlas, TilesArePackedWithoutOverlapAndTheirBoundsAreTheirTexels)
{
    const std::vector<SpotShadowInput> spots(5);
    const std::vector<PointShadowInput> points(2);
    ShadowSettings settings;
    settings.local.atlasSize = 512;
    const LocalShadowPlan plan = planLocalShadows(settings, allConventions()[0], {}, spots, points, kEverywhere);
    ASSERT_EQ(plan.tiles.size(), 17u);
    ASSERT_EQ(plan.tileData.size(), 17u);
    for (std::uint32_t t = 0; t < plan.tiles.size(); ++t) {
        const rhi::Viewport& v = plan.tiles[t].viewport;
        EXPECT_EQ(plan.tiles[t].tile, t);
        const glm::ivec2 first(static_cast<int>(v.x), static_cast<int>(v.y));
        EXPECT_EQ(plan.tileData[t].bounds,
                  (TileTexelBounds{first,
                                   first + glm::ivec2(static_cast<int>(v.width), static_cast<int>(v.height)) - 1}))
            << t;
    }
    expectDisjointTiles(plan);
}

TEST(LocalAtlas, EveryLightGetsTilesDownToTheFloorAndOnlyThenIsReported)
{
    // 40 spot lights and two point lights (52 tiles) fit a 1024 atlas once lowered; point 1 casts nothing.
    const std::vector<SpotShadowInput> spots(40);
    std::vector<PointShadowInput> points(3);
    points[1].strength = 0.0f;
    const LocalShadowPlan plan =
        planLocalShadows(ShadowSettings{}, allConventions()[0], {}, spots, points, kEverywhere);
    EXPECT_EQ(plan.tiles.size(), 52u);
    for (const int tile : plan.spotTiles)
        EXPECT_GE(tile, 0);
    EXPECT_EQ(plan.pointShadows[1], -1);
    ASSERT_EQ(plan.report.size(), 1u);
    EXPECT_EQ(plan.report[0].kind, LightKind::Point);
    EXPECT_EQ(plan.report[0].lightIndex, 1u);
    EXPECT_EQ(plan.report[0].reason, "shadow strength is 0");
    EXPECT_FALSE(plan.lowered.empty());
    expectDisjointTiles(plan);

    // A 256 atlas holds sixteen tiles of the 64-texel floor: of 18 equal lights the two of the highest index (the
    // packer's tie break) lose their shadows, with the reason.
    ShadowSettings small;
    small.local.atlasSize = 256;
    small.local.minTileResolution = 64;
    const std::vector<SpotShadowInput> many(18);
    const LocalShadowPlan full = planLocalShadows(small, allConventions()[0], {}, many, {}, kEverywhere);
    EXPECT_EQ(full.tiles.size(), 16u);
    EXPECT_EQ(full.spotTiles[16], -1);
    EXPECT_EQ(full.spotTiles[17], -1);
    ASSERT_EQ(full.report.size(), 2u);
    EXPECT_EQ(full.report[0].reason, "no shadow: the 256 x 256 local atlas has no room for its 1 tile(s) of the floor "
                                     "size 64 x 64 with every light of higher priority at that size");
    expectDisjointTiles(full);
}

TEST(LocalAtlas, NearerLightsKeepMoreResolutionWhenSpaceRunsOut)
{
    // Spot lights ever farther ahead of the camera: their reach covers less of the screen, so they ask for less and
    // are lowered first.
    std::vector<SpotShadowInput> spots;
    for (int i = 0; i < 12; ++i)
        spots.push_back({.position = {0.0f, 2.0f, -6.0f - 8.0f * static_cast<float>(i)}, .range = 5.0f});
    ShadowSettings settings;
    settings.local.atlasSize = 512;
    const LocalShadowPlan plan = planLocalShadows(settings, allConventions()[0], {}, spots, {}, kEverywhere);
    ASSERT_EQ(plan.tiles.size(), spots.size());
    for (std::size_t i = 1; i < spots.size(); ++i)
        EXPECT_LE(plan.tiles[i].viewport.width, plan.tiles[i - 1].viewport.width) << i;
    EXPECT_GT(plan.tiles.front().viewport.width, plan.tiles.back().viewport.width);
    expectDisjointTiles(plan);
}

TEST(LocalAtlas, TilesStayPutFromFrameToFrameWhileLightsComeAndGo)
{
    std::vector<SpotShadowInput> spots;
    for (int i = 0; i < 8; ++i)
        spots.push_back({.position = {2.0f * static_cast<float>(i), 2.0f, -10.0f}, .range = 6.0f});
    const std::vector<PointShadowInput> points{{.position = {0, 2, -20}, .range = 6.0f}};
    const ShadowCamera camera;
    const rhi::Conventions conventions = allConventions()[0];
    // An atlas with room for every tile at the size it asks for: no light is lowered, so a light's tiles follow its
    // own inputs alone.
    ShadowSettings settings;
    settings.local.atlasSize = 4096;
    const LocalShadowPlan first = planLocalShadows(settings, conventions, camera, spots, points, kEverywhere);
    ASSERT_TRUE(first.lowered.empty());
    // The same inputs: every tile where it was.
    const LocalShadowPlan again =
        planLocalShadows(settings, conventions, camera, spots, points, kEverywhere, first.allocation);
    ASSERT_EQ(again.tiles.size(), first.tiles.size());
    for (std::size_t t = 0; t < first.tiles.size(); ++t) {
        EXPECT_EQ(again.tiles[t].viewport.x, first.tiles[t].viewport.x) << t;
        EXPECT_EQ(again.tiles[t].viewport.y, first.tiles[t].viewport.y) << t;
        EXPECT_EQ(again.tiles[t].viewport.width, first.tiles[t].viewport.width) << t;
    }
    for (const PackedLight& light : again.allocation.pack.lights)
        EXPECT_FALSE(light.moved) << light.lightId;
    // The last spot light gone and the first moved a little: the others keep their tiles (lights are known to the
    // packer by kind and index: spot light i is packer light 2i).
    std::vector<SpotShadowInput> fewer(spots.begin(), spots.end() - 1);
    fewer[0].position.x += 0.05f;
    const LocalShadowPlan next =
        planLocalShadows(settings, conventions, camera, fewer, points, kEverywhere, again.allocation);
    ASSERT_EQ(next.tiles.size(), first.tiles.size() - 1);
    for (std::size_t i = 0; i < fewer.size(); ++i) {
        const rhi::Viewport& was = first.tiles[static_cast<std::size_t>(first.spotTiles[i])].viewport;
        const rhi::Viewport& is = next.tiles[static_cast<std::size_t>(next.spotTiles[i])].viewport;
        EXPECT_EQ(glm::vec3(is.x, is.y, is.width), glm::vec3(was.x, was.y, was.width)) << i;
    }
    const auto pointTiles = [](const LocalShadowPlan& plan) {
        std::vector<float> places;
        for (std::uint32_t f = 0; f < cubeFaceCount; ++f) {
            const rhi::Viewport& v = plan.tiles[static_cast<std::size_t>(plan.pointShadows[0]) + f].viewport;
            places.insert(places.end(), {v.x, v.y, v.width});
        }
        return places;
    };
    EXPECT_EQ(pointTiles(next), pointTiles(first));
    expectDisjointTiles(next);
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
    EXPECT_EQ(plan.tiles.size(), 1u);
    ASSERT_EQ(plan.report.size(), 3u);
    EXPECT_EQ(plan.report[0].reason, "no shadow caster is within its reach");
    EXPECT_EQ(plan.report[1].reason, "no shadow caster is within its reach");
    EXPECT_EQ(plan.report[2].reason, "its reach begins at view depth 195, beyond the shadow distance 100");
}

} // namespace
} // namespace penumbra::shadows
