// Depth fit: the histogram of the visible view depths, its partition into cascades, the tiles' half sizes on a grid
// with hysteresis, and the planner's tiles around the samples' footprints.
#include "ShadowTestSupport.hpp"
#include "penumbra/shadows/CascadeSelection.hpp"
#include "penumbra/shadows/DepthFit.hpp"
#include "penumbra/shadows/DirectionalShadowPlanner.hpp"
#include "penumbra/shadows/LightBasis.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace penumbra::shadows {
namespace {

// A histogram over a 100 m shadow distance with `count` samples in the bin of each depth, their light-space footprint
// (slot 0) a square of half size `half` about the origin.
DepthHistogram histogramOf(std::initializer_list<std::pair<float, float>> depthsAndHalves, std::uint32_t count = 100)
{
    DepthHistogram h;
    h.firstOctave = depthHistogramFirstOctave(100.0f);
    h.bins.resize(kDepthHistogramBins);
    h.lightDirections = {glm::vec3(0.0f, -1.0f, 0.0f)};
    for (const auto& [depth, half] : depthsAndHalves) {
        DepthHistogramBin& bin = h.bins[depthHistogramBin(h.firstOctave, depth)];
        bin.count += count;
        bin.footprints[0] = {-half, -half, half, half};
    }
    return h;
}

TEST(DepthFit, BinsAreTheStepGridAtEightStepsPerOctave)
{
    // 8 steps per octave: 0.125 m steps in [1, 2), 4 m steps in [32, 64).
    EXPECT_EQ(depthFitStep(1.5f, 8), 0.125f);
    EXPECT_EQ(depthFitStep(40.0f, 8), 4.0f);
    // 100 m: the last octave is [64, 128), the first 16 below.
    const int first = depthHistogramFirstOctave(100.0f);
    EXPECT_EQ(first, 7 - 16);
    EXPECT_EQ(depthHistogramBinStart(first, kDepthHistogramBins), 128.0f);
    for (const float depth : {0.3f, 1.3f, 2.0f, 37.0f, 99.0f}) {
        const std::uint32_t bin = depthHistogramBin(first, depth);
        EXPECT_LE(depthHistogramBinStart(first, bin), depth) << depth;
        EXPECT_GT(depthHistogramBinStart(first, bin + 1), depth) << depth;
        EXPECT_EQ(depthHistogramBinStart(first, bin + 1) - depthHistogramBinStart(first, bin), depthFitStep(depth, 8));
    }
    // Depths outside the 16 octaves are clamped into the first and last bins.
    EXPECT_EQ(depthHistogramBin(first, 1e-6f), 0u);
    EXPECT_EQ(depthHistogramBin(first, 1e6f), kDepthHistogramBins - 1);
    const DepthHistogram h = histogramOf({{1.3f, 1.0f}, {37.0f, 20.0f}});
    EXPECT_EQ(depthHistogramRange(h), (ViewDepthRange{1.25f, 40.0f}));
    EXPECT_FALSE(depthHistogramRange(histogramOf({})));
}

TEST(DepthFit, FootprintIsTheUnionOfTheBinsWithSamples)
{
    DepthHistogram h = histogramOf({{2.0f, 1.0f}, {3.0f, 2.0f}});
    h.bins[depthHistogramBin(h.firstOctave, 2.5f)].footprints[0] = {-50.0f, -50.0f, 50.0f, 50.0f}; // no samples
    const std::uint32_t first = depthHistogramBin(h.firstOctave, 2.0f), last = depthHistogramBin(h.firstOctave, 3.0f);
    const std::optional<Bounds> both = depthHistogramFootprint(h, 0, first, last + 1);
    ASSERT_TRUE(both);
    EXPECT_EQ(both->min, glm::vec3(-2.0f, -2.0f, 0.0f));
    EXPECT_EQ(both->max, glm::vec3(2.0f, 2.0f, 0.0f));
    EXPECT_FALSE(depthHistogramFootprint(h, 0, first + 1, last));
}

// Most samples near the camera in a small footprint, a few far in a wide one: the partition gives the near crowd its
// own cascades instead of spacing the splits evenly in log depth.
TEST(DepthFit, PartitionPutsTheSamplesTexelsHighest)
{
    DepthHistogram h = histogramOf({{2.0f, 1.0f}, {2.5f, 1.2f}, {3.0f, 1.5f}, {3.5f, 1.8f}}, 1000);
    for (const auto& [depth, half] : {std::pair{20.0f, 15.0f}, {40.0f, 30.0f}}) {
        DepthHistogramBin& bin = h.bins[depthHistogramBin(h.firstOctave, depth)];
        bin.count = 10;
        bin.footprints[0] = {-half, -half, half, half};
    }
    const std::vector<std::uint32_t> edges = depthFitPartition(h, 4, 1, {}, 0.0f);
    ASSERT_EQ(edges.size(), 5u);
    EXPECT_EQ(edges.front(), depthHistogramBin(h.firstOctave, 2.0f));
    EXPECT_EQ(edges.back(), depthHistogramBin(h.firstOctave, 40.0f) + 1);
    // Three cascades for the near samples, one for the far ones (the empty bins between go to the nearer cascade).
    EXPECT_GT(edges[3], depthHistogramBin(h.firstOctave, 3.5f));
    EXPECT_LE(edges[3], depthHistogramBin(h.firstOctave, 20.0f));
    EXPECT_TRUE(std::is_sorted(edges.begin(), edges.end()));
    const CascadeSplits splits = depthFitSplits(h, edges, 0.1f, 150.0f, 100.0f);
    EXPECT_EQ(splits.count, 4u);
    EXPECT_EQ(splits.nearOf(0), 2.0f);
    EXPECT_EQ(splits.farOf(3), 44.0f);
    EXPECT_LE(splits.farOf(2), 20.0f);
    EXPECT_LE(splits.farOf(1), 3.0f);
}

TEST(DepthFit, KeptPartitionStaysWhileItHoldsTheSamplesAndCostsLittleMore)
{
    const DepthHistogram h = histogramOf({{2.0f, 1.0f}, {4.0f, 2.0f}, {8.0f, 4.0f}, {16.0f, 8.0f}, {32.0f, 16.0f}});
    const std::vector<std::uint32_t> best = depthFitPartition(h, 4, 1, {}, 0.0f);
    // A partition that splits elsewhere: kept within a generous tolerance, dropped without one.
    std::vector<std::uint32_t> other = best;
    other[2] += 1;
    EXPECT_EQ(depthFitPartition(h, 4, 1, other, 10.0f), other);
    EXPECT_EQ(depthFitPartition(h, 4, 1, other, 0.0f), best);
    // A kept partition that misses a sample is dropped whatever the tolerance.
    std::vector<std::uint32_t> missing = best;
    missing.back() -= 1;
    EXPECT_EQ(depthFitPartition(h, 4, 1, missing, 10.0f), best);
}

TEST(DepthFit, SplitsStayWithinTheCameraAndTheShadowDistance)
{
    DepthHistogram h = histogramOf({{2.0f, 1.0f}, {120.0f, 1.0f}});
    h.bins[0].count = 5; // nearer than the first octave
    const std::vector<std::uint32_t> edges = depthFitPartition(h, 4, 1, {}, 0.0f);
    const CascadeSplits splits = depthFitSplits(h, edges, 0.1f, 150.0f, 100.0f);
    EXPECT_EQ(splits.nearOf(0), 0.1f);
    EXPECT_EQ(splits.farOf(3), 100.0f);
    for (std::uint32_t c = 0; c < 4; ++c)
        EXPECT_LE(splits.nearOf(c), splits.farOf(c));
}

TEST(DepthFit, HalfSizeIsOnTheGridWithHysteresis)
{
    // 8 steps per octave: 0.5 steps in [4, 8).
    EXPECT_EQ(depthFitHalfSize(5.1f, std::nullopt, 8, 1.0f), 5.5f);
    EXPECT_EQ(depthFitHalfSize(5.5f, std::nullopt, 8, 1.0f), 5.5f);
    // Kept while the required size stays within 1 + hysteresis steps below it.
    EXPECT_EQ(depthFitHalfSize(4.6f, 5.5f, 8, 1.0f), 5.5f);
    EXPECT_EQ(depthFitHalfSize(4.6f, 5.5f, 8, 0.0f), 5.0f);
    EXPECT_EQ(depthFitHalfSize(4.4f, 5.5f, 8, 1.0f), 4.5f);
    // Larger than kept: grows at once where the tile must hold the footprint (the last cascade's).
    EXPECT_EQ(depthFitHalfSize(5.6f, 5.5f, 8, 4.0f), 6.0f);
    // A nearer cascade's tile may fall short by half the hysteresis: the next tile serves the samples past its edge.
    EXPECT_EQ(depthFitHalfSize(5.7f, 5.5f, 8, 1.0f, true), 5.5f);
    EXPECT_EQ(depthFitHalfSize(5.8f, 5.5f, 8, 1.0f, true), 6.0f);
    // Unquantized: as required.
    EXPECT_EQ(depthFitHalfSize(5.1f, 5.5f, 0, 1.0f), 5.1f);
}

// The planner: depth fit without a histogram is the close fit with its tiles' sizes on the grid; with one, each tile is
// fitted around its samples' footprint, much finer than the stable fit's spheres, and the plan keeps its partition and
// half sizes.
TEST(DepthFit, PlannerFitsTheTilesToTheSamples)
{
    ShadowCamera camera = testing::uprightCamera(glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0.0f, -0.2f, 1.0f));
    camera.aspect = 16.0f / 9.0f;
    camera.farPlane = 150.0f;
    ShadowSettings settings;
    const std::vector<DirectionalShadowLightInput> lights{{glm::normalize(glm::vec3(-0.4f, -1.0f, 0.5f))}};
    const std::vector<Bounds> casters{{glm::vec3(-1.0f), glm::vec3(1.0f)}};
    const DirectionalShadowPlan stable =
        planDirectionalShadows(settings, testing::kZeroToOneReversed, camera, lights, casters);
    settings.directional.projection = CascadeProjection::Close;
    const DirectionalShadowPlan close =
        planDirectionalShadows(settings, testing::kZeroToOneReversed, camera, lights, casters);
    settings.directional.projection = CascadeProjection::DepthFit;
    const DirectionalShadowPlan fallback =
        planDirectionalShadows(settings, testing::kZeroToOneReversed, camera, lights, casters);
    EXPECT_FALSE(fallback.depthFit);
    DepthHistogram h = histogramOf({{2.0f, 1.0f}, {3.0f, 1.5f}, {6.0f, 3.0f}, {12.0f, 6.0f}, {30.0f, 15.0f}});
    h.lightDirections = {lights[0].direction};
    const DirectionalShadowPlan fitted =
        planDirectionalShadows(settings, testing::kZeroToOneReversed, camera, lights, casters, {&h, nullptr});
    ASSERT_EQ(fitted.lights.size(), 1u);
    ASSERT_TRUE(fitted.depthFit);
    EXPECT_EQ(fitted.uniforms.cascadeProjection, CascadeProjection::DepthFit);
    for (std::uint32_t c = 0; c < 4; ++c) {
        const float closeTexel = close.lights[0].cascades[c].fit.texelSize;
        EXPECT_GE(fallback.lights[0].cascades[c].fit.texelSize, closeTexel);
        EXPECT_LE(fallback.lights[0].cascades[c].fit.texelSize, 1.125f * closeTexel);
        EXPECT_EQ(fitted.depthFit->halfSizes[c], fitted.lights[0].cascades[c].fit.halfSize);
        EXPECT_LT(fitted.lights[0].cascades[c].fit.texelSize, 0.5f * stable.lights[0].cascades[c].fit.texelSize)
            << "cascade " << c;
    }
    // The same histogram with the plan's kept state gives the same plan.
    const DirectionalShadowPlan again =
        planDirectionalShadows(settings, testing::kZeroToOneReversed, camera, lights, casters, {&h, &*fitted.depthFit});
    EXPECT_EQ(again.depthFit, fitted.depthFit);
    // A histogram measured along another light's direction: the footprints are not used, the slices' bounds are.
    h.lightDirections = {glm::vec3(0.0f, -1.0f, 0.0f)};
    const DirectionalShadowPlan other =
        planDirectionalShadows(settings, testing::kZeroToOneReversed, camera, lights, casters, {&h, nullptr});
    EXPECT_GT(other.lights[0].cascades[0].fit.texelSize, fitted.lights[0].cascades[0].fit.texelSize);
}

// Two suns from opposite sides over ground points the camera sees: each light's tiles are fitted around its own
// footprint of the points, so each light selects in its own tiles; the first light's selection would send the second
// light's lookups outside its tiles.
TEST(DepthFit, EachLightSelectsInItsOwnTiles)
{
    ShadowCamera camera = testing::uprightCamera(glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0.0f, -0.3f, 1.0f));
    camera.aspect = 16.0f / 9.0f;
    camera.farPlane = 150.0f;
    ShadowSettings settings;
    settings.directional.projection = CascadeProjection::DepthFit;
    const std::vector<DirectionalShadowLightInput> lights{{glm::normalize(glm::vec3(-1.0f, -1.0f, 0.3f))},
                                                          {glm::normalize(glm::vec3(1.0f, -0.7f, -0.2f))}};
    const std::vector<Bounds> casters{{glm::vec3(-20.0f, 0.0f, 0.0f), glm::vec3(20.0f, 1.0f, 40.0f)}};
    DepthHistogram h = histogramOf({});
    h.lightDirections = {lights[0].direction, lights[1].direction};
    std::vector<glm::vec3> ground;
    for (float z = 2.0f; z < 40.0f; z += 0.5f)
        for (float x = -0.6f * z; x <= 0.6f * z; x += 0.05f * z)
            ground.push_back({x, 0.0f, z});
    for (const glm::vec3& p : ground) {
        DepthHistogramBin& bin =
            h.bins[depthHistogramBin(h.firstOctave, glm::dot(p - camera.position, camera.forward))];
        for (std::uint32_t s = 0; s < 2; ++s) {
            const glm::vec3 l = lightBasis(lights[s].direction).toLight(p);
            glm::vec4& f = bin.footprints[s];
            f = bin.count == 0
                    ? glm::vec4(l.x, l.y, l.x, l.y)
                    : glm::vec4(std::min(f.x, l.x), std::min(f.y, l.y), std::max(f.z, l.x), std::max(f.w, l.y));
        }
        bin.count += 1;
    }
    const DirectionalShadowPlan plan =
        planDirectionalShadows(settings, testing::kZeroToOneReversed, camera, lights, casters, {&h, nullptr});
    ASSERT_EQ(plan.lights.size(), 2u);
    const DirectionalShadowUniforms& u = plan.uniforms;
    // Whether light `slot`'s tile of cascade `c` holds the point.
    const auto holds = [&](std::uint32_t slot, std::uint32_t c, glm::vec3 p) {
        const std::size_t tile = plan.lights[slot].cascades.at(c).tile;
        const glm::vec2 texel = glm::vec2(u.worldToAtlas[tile] * glm::vec4(p, 1.0f)) * u.atlasSize;
        const TileTexelBounds& b = u.tileBounds[tile];
        return texel.x >= float(b.first.x) && texel.y >= float(b.first.y) && texel.x <= float(b.last.x + 1) &&
               texel.y <= float(b.last.y + 1);
    };
    std::size_t firstLightsMiss = 0;
    for (const glm::vec3& p : ground) {
        const float depth = glm::dot(p - camera.position, camera.forward);
        for (std::uint32_t slot = 0; slot < 2; ++slot) {
            const CascadeSelection s = selectCascade(u, p, depth, slot);
            ASSERT_LT(s.index, 4u) << "slot " << slot << " misses the point " << p.x << ", " << p.z;
            EXPECT_TRUE(holds(slot, s.index, p)) << "slot " << slot;
        }
        firstLightsMiss += !holds(1, selectCascade(u, p, depth, 0).index, p);
    }
    // 30 of about 1 900 points: the first light's selection would look them up outside the second light's tiles.
    EXPECT_GT(firstLightsMiss, 0u) << "the lights' tiles differ enough to show the point";
}

} // namespace
} // namespace penumbra::shadows
