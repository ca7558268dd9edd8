// The depth fit's window search (summed-area tables, inclusion-exclusion over the cleared windows, branch and bound)
// against brute force on random rasters: the same sums, mean-shift corners and heaviest windows, bit for bit.
#include "penumbra/shadows/OccupancyRaster.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

// The raster with the cleared windows' cells zeroed, as the search first did it.
std::vector<std::int64_t> clearedMass(const OccupancyRaster& r, const std::vector<RasterWindow>& cleared)
{
    std::vector<std::int64_t> mass = r.mass;
    for (const RasterWindow& w : cleared)
        for (int y = std::max(w.y, 0); y < std::min(w.y + w.k, r.ny); ++y)
            for (int x = std::max(w.x, 0); x < std::min(w.x + w.k, r.nx); ++x)
                mass[static_cast<std::size_t>(y * r.nx + x)] = 0;
    return mass;
}

std::int64_t bruteSum(const OccupancyRaster& r, const std::vector<std::int64_t>& mass, int x, int y, int k)
{
    std::int64_t s = 0;
    for (int j = std::max(y, 0); j < std::min(y + k, r.ny); ++j)
        for (int i = std::max(x, 0); i < std::min(x + k, r.nx); ++i)
            s += mass[static_cast<std::size_t>(j * r.nx + i)];
    return s;
}

// The mean cell centre in doubles (exact at these magnitudes), then floor(mean - k / 2 + 1/2).
glm::ivec2 bruteCorner(const OccupancyRaster& r, const std::vector<std::int64_t>& mass, int x, int y, int k)
{
    double mx = 0.0, my = 0.0, total = 0.0;
    for (int j = std::max(y, 0); j < std::min(y + k, r.ny); ++j)
        for (int i = std::max(x, 0); i < std::min(x + k, r.nx); ++i) {
            const auto m = static_cast<double>(mass[static_cast<std::size_t>(j * r.nx + i)]);
            mx += m * (i + 0.5);
            my += m * (j + 0.5);
            total += m;
        }
    if (total <= 0.0)
        return {x, y};
    return {static_cast<int>(std::floor(mx / total - 0.5 * k + 0.5)),
            static_cast<int>(std::floor(my / total - 0.5 * k + 0.5))};
}

TEST(OccupancyRaster, WindowSearchMatchesBruteForceOnRandomRasters)
{
    std::mt19937 random(7);
    for (int trial = 0; trial < 40; ++trial) {
        OccupancyRaster r;
        r.nx = std::uniform_int_distribution(1, 48)(random);
        r.ny = std::uniform_int_distribution(1, 48)(random);
        r.mass.resize(static_cast<std::size_t>(r.nx * r.ny));
        // Sparse clusters of small counts: plateaus and ties, where the order of the search matters.
        for (std::int64_t& m : r.mass)
            m = std::uniform_int_distribution(0, 3)(random) == 0 ? std::uniform_int_distribution(0, 4)(random) : 0;
        const RasterWindowSums all(r);
        std::vector<RasterWindow> cleared;
        for (int tile = 0; tile < 4; ++tile) {
            const std::vector<std::int64_t> mass = clearedMass(r, cleared);
            const RasterWindowSums::Without sums = all.without(cleared);
            const int k = std::uniform_int_distribution(1, 52)(random);
            RasterWindow best{0, 0, k, -1};
            for (int y = 0; y + k <= std::max(r.ny, k); ++y)
                for (int x = 0; x + k <= std::max(r.nx, k); ++x)
                    if (const std::int64_t s = bruteSum(r, mass, x, y, k); s > best.mass)
                        best = {x, y, k, s};
            const RasterWindow found = sums.heaviest(k);
            ASSERT_EQ(std::tie(found.x, found.y, found.k, found.mass), std::tie(best.x, best.y, best.k, best.mass))
                << "trial " << trial << ", tile " << tile;
            for (int probe = 0; probe < 8; ++probe) {
                const int x = std::uniform_int_distribution(-k, r.nx)(random);
                const int y = std::uniform_int_distribution(-k, r.ny)(random);
                ASSERT_EQ(sums.sum(x, y, k), bruteSum(r, mass, x, y, k));
                ASSERT_EQ(sums.centredCorner(x, y, k), bruteCorner(r, mass, x, y, k));
            }
            // The next tile clears a window near the heaviest, reaching past the raster at times.
            cleared.push_back({best.x + std::uniform_int_distribution(-3, 3)(random),
                               best.y + std::uniform_int_distribution(-3, 3)(random), k, 0});
        }
    }
}

} // namespace
} // namespace penumbra::shadows
