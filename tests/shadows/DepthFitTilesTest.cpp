// Depth fit's tiles placed over the occupancy grids: around clusters of samples in light space, kept while they
// cost little more, and in the planner every sample still held by the last tile.
#include "ShadowTestSupport.hpp"
#include "penumbra/shadows/CascadeSelection.hpp"
#include "penumbra/shadows/DepthFitTiles.hpp"
#include "penumbra/shadows/DirectionalShadowPlanner.hpp"
#include "penumbra/shadows/LightBasis.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace penumbra::shadows {
namespace {

// A histogram over a 64 m shadow distance, one light, with occupancy grids about the light-space origin.
DepthHistogram emptyHistogram(glm::vec3 light = {0.0f, -1.0f, 0.0f})
{
    DepthHistogram h;
    h.firstOctave = depthHistogramFirstOctave(64.0f);
    h.bins.resize(kDepthHistogramBins);
    h.lightDirections = {light};
    h.occupancy.resize(1);
    for (std::uint32_t o = 0; o < kOccupancyOctaves; ++o) {
        h.occupancy[0].push_back(occupancyGridAbout(h.firstOctave, o, glm::vec2(0.0f)));
        h.occupancy[0].back().counts.assign(kOccupancyCells * kOccupancyCells, 0u);
    }
    return h;
}

// `count` samples at view depth `depth` and light-space x, y: the reduction's counting, on the CPU.
void addSamples(DepthHistogram& h, float depth, glm::vec2 light, std::uint32_t count)
{
    const std::uint32_t b = depthHistogramBin(h.firstOctave, depth);
    DepthHistogramBin& bin = h.bins[b];
    glm::vec4& f = bin.footprints[0];
    f = bin.count == 0 ? glm::vec4(light, light)
                       : glm::vec4(glm::min(glm::vec2(f), light), glm::max(glm::vec2(f.z, f.w), light));
    bin.count += count;
    OccupancyGrid& grid = h.occupancy[0][occupancyOctave(b)];
    const glm::ivec2 cell = glm::clamp(glm::ivec2(glm::floor((light - grid.origin) / grid.cellSize)), glm::ivec2(0),
                                       glm::ivec2(kOccupancyCells - 1));
    grid.counts[cell.y * kOccupancyCells + cell.x] += count;
}

// Two dense clusters 30 m apart (1 m across, at 6 and 20 m of depth) over a sparse 80 m field.
DepthHistogram clusters(glm::vec2 shift = glm::vec2(0.0f))
{
    DepthHistogram h = emptyHistogram();
    for (float x = -40.0f; x <= 40.0f; x += 4.0f)
        for (float y = -40.0f; y <= 40.0f; y += 4.0f)
            addSamples(h, 30.0f, {x, y}, 1);
    for (float x = 0.0f; x < 1.0f; x += 0.25f)
        for (float y = 0.0f; y < 1.0f; y += 0.25f) {
            addSamples(h, 6.0f, glm::vec2(10.1f + x, 10.1f + y) + shift, 50);
            addSamples(h, 20.0f, glm::vec2(-19.9f + x, 5.1f + y) + shift, 30);
        }
    return h;
}

TEST(DepthFitTiles, TilesAreSmallSquaresAroundTheClusters)
{
    const DepthHistogram h = clusters();
    const DepthFitTiles tiles = depthFitTiles(h, {.placed = 3, .lastHalfSize = 48.0f, .servedShare = 0.99f});
    ASSERT_EQ(tiles.halfSizes.size(), 3u);
    ASSERT_EQ(tiles.centres.size(), 3u);
    // Each cluster (its samples 0.75 m across) is served by a tile of at most a few metres about it, not one square
    // over both, 30 m apart.
    for (const glm::vec2 cluster : {glm::vec2(10.475f, 10.475f), glm::vec2(-19.525f, 5.475f)}) {
        bool served = false;
        for (std::size_t c = 0; c < 3; ++c) {
            const glm::vec2 offset = glm::abs(tiles.centres[c][0] - cluster);
            served |= tiles.halfSizes[c] <= 4.0f && std::max(offset.x, offset.y) + 0.375f <= 0.99f * tiles.halfSizes[c];
        }
        EXPECT_TRUE(served) << "cluster at " << cluster.x << ", " << cluster.y;
    }
    for (std::size_t c = 0; c < 3; ++c)
        EXPECT_EQ(depthFitHalfSize(tiles.halfSizes[c], std::nullopt, 8, 1.0f), tiles.halfSizes[c])
            << "on the grid of 8 steps per octave";
    // Without occupancy grids there is nothing to place.
    DepthHistogram none = h;
    none.occupancy.clear();
    EXPECT_TRUE(depthFitTiles(none, {.placed = 3, .lastHalfSize = 48.0f}).halfSizes.empty());
}

TEST(DepthFitTiles, KeptTilesStayWhileTheyCostLittleMore)
{
    const DepthFitTilesInput input{.placed = 3, .lastHalfSize = 48.0f, .servedShare = 0.99f, .toleranceLog2 = 0.125f};
    const DepthFitTiles first = depthFitTiles(clusters(), input);
    DepthFitTilesInput again = input;
    again.kept = &first;
    // The clusters move by 2 cm: the kept tiles still hold nearly all of them.
    EXPECT_EQ(depthFitTiles(clusters(glm::vec2(0.02f, -0.02f)), again), first);
    // By 6 m: the kept tiles hold neither, and the tiles follow them.
    const DepthFitTiles moved = depthFitTiles(clusters(glm::vec2(6.0f, 0.0f)), again);
    EXPECT_NE(moved, first);
    // Without the tolerance the search's own tiles, which on the unmoved clusters are the kept ones.
    DepthFitTilesInput strict = again;
    strict.toleranceLog2 = 0.0f;
    EXPECT_EQ(depthFitTiles(clusters(), strict), first);
}

// The planner: the placed tiles are finer than the partition's, and every sample is held by some tile (the last
// holds them all), so map-based selection finds a cascade for each.
TEST(DepthFitTiles, PlannerPlacesTheTilesAndTheLastHoldsEverySample)
{
    ShadowCamera camera = testing::uprightCamera(glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0.0f, -0.3f, 1.0f));
    camera.aspect = 16.0f / 9.0f;
    camera.farPlane = 150.0f;
    ShadowSettings settings;
    settings.maxDistance = 64.0f;
    settings.directional.projection = CascadeProjection::DepthFit;
    const std::vector<DirectionalShadowLightInput> lights{{glm::normalize(glm::vec3(-0.5f, -1.0f, 0.3f))}};
    const std::vector<Bounds> casters{{glm::vec3(-40.0f, 0.0f, 0.0f), glm::vec3(40.0f, 1.0f, 64.0f)}};
    const LightBasis basis = lightBasis(lights[0].direction);
    DepthHistogram h = emptyHistogram(lights[0].direction);
    for (std::uint32_t o = 0; o < kOccupancyOctaves; ++o) {
        h.occupancy[0][o] = occupancyGridAbout(h.firstOctave, o, glm::vec2(basis.toLight(camera.position)));
        h.occupancy[0][o].counts.assign(kOccupancyCells * kOccupancyCells, 0u);
    }
    // Ground points the camera sees, and a dense patch of them 4 to 6 m ahead, off to the side.
    std::vector<glm::vec3> points;
    for (float z = 2.0f; z < 60.0f; z += 1.0f)
        for (float x = -0.6f * z; x <= 0.6f * z; x += 0.05f * z)
            points.push_back({x, 0.0f, z});
    for (float z = 4.0f; z < 6.0f; z += 0.05f)
        for (float x = 1.0f; x < 3.0f; x += 0.05f)
            points.push_back({x, 0.0f, z});
    for (const glm::vec3& p : points)
        addSamples(h, glm::dot(p - camera.position, camera.forward), glm::vec2(basis.toLight(p)), 1);
    const DirectionalShadowPlan plan =
        planDirectionalShadows(settings, testing::kZeroToOneReversed, camera, lights, casters, {&h, nullptr});
    ASSERT_TRUE(plan.depthFit);
    ASSERT_EQ(plan.depthFit->centres.size(), 3u);
    std::size_t servedByPlaced = 0;
    for (const glm::vec3& p : points) {
        const CascadeSelection s = selectCascade(plan.uniforms, p, glm::dot(p - camera.position, camera.forward), 0);
        ASSERT_LT(s.index, 4u) << "no tile holds " << p.x << ", " << p.z;
        servedByPlaced += s.index < 3;
    }
    EXPECT_GT(servedByPlaced, points.size() / 2);
    // The same histogram with the plan's kept state gives the same plan.
    const DirectionalShadowPlan again =
        planDirectionalShadows(settings, testing::kZeroToOneReversed, camera, lights, casters, {&h, &*plan.depthFit});
    EXPECT_EQ(again.depthFit, plan.depthFit);
}

} // namespace
} // namespace penumbra::shadows
