#pragma once

#include <cstdint>
#include <span>
#include <vector>
#include <glm/vec2.hpp>

namespace penumbra::shadows {

// Raster masses are samples in units of 1/kRasterMassUnit: integers, so that every window sum is exact whatever the
// order it is added in (summed-area tables, inclusion-exclusion), and the fast window search below gives the
// brute-force answer bit for bit.
inline constexpr std::int64_t kRasterMassUnit = std::int64_t{1} << 20;

// One light slot's samples on a raster anchored to a multiple of its cell: mass per cell, rows of nx.
struct OccupancyRaster {
    glm::vec2 origin{0.0f};
    float cell = 0.0f;
    int nx = 0;
    int ny = 0;
    std::vector<std::int64_t> mass;
};

// A k x k window of raster cells from x, y (it may reach past the raster, which holds nothing there) and its mass.
struct RasterWindow {
    int x = 0;
    int y = 0;
    int k = 0;
    std::int64_t mass = 0;
};

// Window sums over a raster whose `cleared` windows' cells are taken out (the samples earlier tiles serve): summed-area
// tables of the mass and its first moments (Crow, "Summed-Area Tables for Texture Mapping", SIGGRAPH 1984), built once,
// and inclusion-exclusion over the cleared windows, so that no query copies or rebuilds the raster.
class RasterWindowSums {
public:
    explicit RasterWindowSums(const OccupancyRaster& raster);

    // The window's mass outside the cleared windows.
    std::int64_t sum(int x, int y, int k, std::span<const RasterWindow> cleared) const;
    // The corner of the k x k window centred on the mean cell centre of what the window at x, y holds outside the
    // cleared windows (floor of the exact mean); x, y where it holds nothing. One mean-shift step.
    glm::ivec2 centredCorner(int x, int y, int k, std::span<const RasterWindow> cleared) const;
    // The k x k window that holds the most outside the cleared windows, the first in row order among equals.
    RasterWindow heaviest(int k, std::span<const RasterWindow> cleared) const;

    std::int64_t total() const { return table(mass_, nx_, ny_); }

private:
    struct Rect {
        int x0 = 0;
        int y0 = 0;
        int x1 = 0;
        int y1 = 0;
        bool empty() const { return x0 >= x1 || y0 >= y1; }
    };
    struct Term {
        Rect rect;
        std::int64_t sign = 0;
    };

    Rect clipped(int x, int y, int w, int h) const;
    static Rect intersection(const Rect& a, const Rect& b);
    std::vector<Term> terms(std::span<const RasterWindow> cleared) const;
    std::int64_t table(const std::vector<std::int64_t>& t, int x, int y) const
    {
        return t[static_cast<std::size_t>(y * (nx_ + 1) + x)];
    }
    std::int64_t rectSum(const std::vector<std::int64_t>& t, const Rect& r) const;
    std::int64_t maskedSum(const std::vector<std::int64_t>& t, const Rect& r, std::span<const Term> terms) const;

    int nx_ = 0;
    int ny_ = 0;
    std::vector<std::int64_t> mass_; // (nx + 1) x (ny + 1) summed-area tables
    std::vector<std::int64_t> massX_; // of mass times the cell's x index
    std::vector<std::int64_t> massY_; // of mass times the cell's y index
};

} // namespace penumbra::shadows
