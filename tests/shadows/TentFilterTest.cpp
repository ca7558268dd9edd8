#include "penumbra/shadows/TentFilter.hpp"
#include "penumbra/shadows/TentFilterReference.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <map>
#include <random>

namespace penumbra::shadows {
namespace {

constexpr ShadowFilter allFilters[] = {ShadowFilter::PCF2x2, ShadowFilter::PCF3x3, ShadowFilter::PCF5x5,
                                       ShadowFilter::PCF7x7};

// Expected weight of texel i for a filter centred at c, computed independently of the library:
// 2x2 is the bilinear hat at texel centres; NxN integrates a tent of base N over the texel (midpoint rule).
double expectedTexelWeight(ShadowFilter filter, int i, double c)
{
    if (filter == ShadowFilter::PCF2x2)
        return std::max(0.0, 1.0 - std::abs(c - (i + 0.5)));
    const double h = 0.5 * filterSize(filter);
    const int steps = 1000;
    double area = 0.0;
    for (int s = 0; s < steps; ++s) {
        const double x = i + (s + 0.5) / steps;
        area += std::max(0.0, 1.0 - std::abs(x - c) / h) / h / steps;
    }
    return area;
}

// The texel weights the taps actually apply: each tap's weight spread by its bilinear fractions.
std::map<std::pair<int, int>, double> effectiveKernel(const ShadowTaps& taps, glm::vec2 size)
{
    std::map<std::pair<int, int>, double> kernel;
    for (const ShadowTap& tap : taps.view()) {
        const glm::vec2 p = tap.uv * size - 0.5f;
        const glm::vec2 base = glm::floor(p);
        const glm::vec2 f = p - base;
        const int x = static_cast<int>(base.x);
        const int y = static_cast<int>(base.y);
        kernel[{x, y}] += tap.weight * (1.0 - f.x) * (1.0 - f.y);
        kernel[{x + 1, y}] += tap.weight * f.x * (1.0 - f.y);
        kernel[{x, y + 1}] += tap.weight * (1.0 - f.x) * f.y;
        kernel[{x + 1, y + 1}] += tap.weight * f.x * f.y;
    }
    return kernel;
}

TEST(TentFilter, WeightsSumToOneForEveryFilterAndOffset)
{
    const glm::vec2 size(1024.0f);
    for (ShadowFilter filter : allFilters) {
        for (int i = 0; i <= 64; ++i) {
            const float offset = static_cast<float>(i) / 64.0f;
            const glm::vec2 uv = (glm::vec2(300.0f, 517.0f) + glm::vec2(offset, 1.0f - offset * 0.5f)) / size;
            const ShadowTaps taps = tentFilterTaps(filter, uv, size);
            EXPECT_EQ(taps.count, filterTapCount(filter));
            double sum = 0.0;
            for (const ShadowTap& tap : taps.view())
                sum += tap.weight;
            EXPECT_NEAR(sum, 1.0, 1e-6) << "filter " << filterSize(filter) << " offset " << offset;
            const TexelWeights w = tentTexelWeights(filter, 300.0f + offset);
            double texelSum = 0.0;
            for (int k = 0; k < w.count; ++k)
                texelSum += w.weights[static_cast<std::size_t>(k)];
            EXPECT_NEAR(texelSum, 1.0, 1e-6);
        }
    }
}

TEST(TentFilter, TapCounts)
{
    EXPECT_EQ(filterTapCount(ShadowFilter::PCF2x2), 1);
    EXPECT_EQ(filterTapCount(ShadowFilter::PCF3x3), 4);
    EXPECT_EQ(filterTapCount(ShadowFilter::PCF5x5), 9);
    EXPECT_EQ(filterTapCount(ShadowFilter::PCF7x7), 16);
}

TEST(TentFilter, ThreeByThreeMatchesTheDesignDocumentsAreas)
{
    // Tent centred on a texel corner: areas 0.125, 1, 1, 0.125 out of 2.25.
    const TexelWeights w = tentTexelWeights(ShadowFilter::PCF3x3, 10.0f);
    EXPECT_EQ(w.first, 8);
    ASSERT_EQ(w.count, 4);
    EXPECT_NEAR(w.weights[0], 0.125f / 2.25f, 1e-6f);
    EXPECT_NEAR(w.weights[1], 1.0f / 2.25f, 1e-6f);
    EXPECT_NEAR(w.weights[2], 1.0f / 2.25f, 1e-6f);
    EXPECT_NEAR(w.weights[3], 0.125f / 2.25f, 1e-6f);
}

TEST(TentFilter, TapsReproduceTheAnalyticAreaWeightedTent)
{
    const glm::vec2 size(512.0f, 256.0f);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> position(20.0f, 200.0f);
    for (ShadowFilter filter : allFilters) {
        for (int trial = 0; trial < 200; ++trial) {
            const glm::vec2 texel(position(rng), position(rng));
            const auto kernel = effectiveKernel(tentFilterTaps(filter, texel / size, size), size);
            const int reach = filterSize(filter) / 2 + 2;
            for (int y = static_cast<int>(texel.y) - reach; y <= static_cast<int>(texel.y) + reach; ++y) {
                for (int x = static_cast<int>(texel.x) - reach; x <= static_cast<int>(texel.x) + reach; ++x) {
                    const auto found = kernel.find({x, y});
                    const double actual = found == kernel.end() ? 0.0 : found->second;
                    const double expected =
                        expectedTexelWeight(filter, x, texel.x) * expectedTexelWeight(filter, y, texel.y);
                    EXPECT_NEAR(actual, expected, 1e-5) << "filter " << filterSize(filter) << " texel (" << x << ", "
                                                        << y << ") centre (" << texel.x << ", " << texel.y << ")";
                }
            }
        }
    }
}

ShadowDepthGrid randomGrid(std::mt19937& rng, std::uint32_t width, std::uint32_t height)
{
    std::uniform_real_distribution<float> depth(0.0f, 1.0f);
    ShadowDepthGrid grid{width, height, std::vector<float>(width * height)};
    for (float& d : grid.depths)
        d = depth(rng);
    return grid;
}

TEST(TentFilter, ConstantFieldsGiveExactlyLitOrShadowed)
{
    const ShadowDepthGrid grid{32, 32, std::vector<float>(32 * 32, 0.5f)};
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> uv(0.0f, 1.0f);
    for (ShadowFilter filter : allFilters) {
        for (int trial = 0; trial < 100; ++trial) {
            const glm::vec2 at(uv(rng), uv(rng));
            for (rhi::CompareOp op : {rhi::CompareOp::LessOrEqual, rhi::CompareOp::GreaterOrEqual}) {
                const float litDepth = op == rhi::CompareOp::LessOrEqual ? 0.4f : 0.6f;
                const float shadowedDepth = op == rhi::CompareOp::LessOrEqual ? 0.6f : 0.4f;
                EXPECT_EQ(filterShadowWithTaps(grid, filter, at, litDepth, op), 1.0f);
                EXPECT_EQ(filterShadowWithTaps(grid, filter, at, shadowedDepth, op), 0.0f);
                EXPECT_EQ(filterShadowReference(grid, filter, at, shadowedDepth, op), 0.0f);
                EXPECT_NEAR(filterShadowReference(grid, filter, at, litDepth, op), 1.0f, 1e-6f);
            }
        }
    }
}

TEST(TentFilter, TapsAgreeWithTheReferenceOnRandomDepths)
{
    std::mt19937 rng(7);
    const ShadowDepthGrid grid = randomGrid(rng, 64, 48);
    std::uniform_real_distribution<float> uv(0.0f, 1.0f);
    for (ShadowFilter filter : allFilters) {
        for (int trial = 0; trial < 300; ++trial) {
            const glm::vec2 at(uv(rng), uv(rng));
            const float receiver = uv(rng);
            EXPECT_NEAR(filterShadowWithTaps(grid, filter, at, receiver, rhi::CompareOp::LessOrEqual),
                        filterShadowReference(grid, filter, at, receiver, rhi::CompareOp::LessOrEqual), 1e-5f)
                << "filter " << filterSize(filter) << " uv (" << at.x << ", " << at.y << ")";
        }
    }
}

TEST(TentFilter, AHalfShadowedEdgeFiltersToAHalf)
{
    // Left half of the texture occluded (depth 0), right half empty (depth 1); receiver at 0.5.
    ShadowDepthGrid grid{16, 16, std::vector<float>(16 * 16, 1.0f)};
    for (std::uint32_t y = 0; y < 16; ++y)
        for (std::uint32_t x = 0; x < 8; ++x)
            grid.depths[y * 16 + x] = 0.0f;
    for (ShadowFilter filter : allFilters)
        EXPECT_NEAR(filterShadowWithTaps(grid, filter, {0.5f, 0.5f}, 0.5f, rhi::CompareOp::LessOrEqual), 0.5f, 1e-6f)
            << "filter " << filterSize(filter);
}

} // namespace
} // namespace penumbra::shadows
