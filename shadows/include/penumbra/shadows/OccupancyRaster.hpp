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

// Window sums over a raster: summed-area tables of the mass and its first moments (Crow, "Summed-Area Tables for
// Texture Mapping", SIGGRAPH 1984), built once, so that no query copies, clears or rebuilds the raster.
class RasterWindowSums {
public:
    explicit RasterWindowSums(const OccupancyRaster& raster);

    struct Rect {
        int x0 = 0;
        int y0 = 0;
        int x1 = 0;
        int y1 = 0;
        bool empty() const { return x0 >= x1 || y0 >= y1; }
    };

    // The raster with the `cleared` windows' cells taken out (the samples earlier tiles serve), as inclusion-exclusion
    // over them: a rectangle's mass outside them is its own plus each term's sign times its intersection's.
    class Without {
    public:
        Without(const RasterWindowSums& sums, std::span<const RasterWindow> cleared);

        // The k x k window's mass at x, y.
        std::int64_t sum(int x, int y, int k) const;
        // The corner of the k x k window centred on the mean cell centre of what the window at x, y holds (floor of
        // the exact mean); x, y where it holds nothing. One mean-shift step.
        glm::ivec2 centredCorner(int x, int y, int k) const;
        // The k x k window that holds the most, the first in row order among equals.
        RasterWindow heaviest(int k) const;

    private:
        struct Term {
            Rect rect;
            std::int64_t sign = 0;
        };
        std::int64_t masked(const std::vector<std::int64_t>& table, const Rect& r, std::span<const Term> terms) const;

        const RasterWindowSums& sums_;
        std::vector<Term> terms_;
    };

    Without without(std::span<const RasterWindow> cleared) const { return Without(*this, cleared); }
    std::int64_t total() const { return at(mass_, nx_, ny_); }

private:
    Rect clipped(int x, int y, int w, int h) const;
    std::int64_t at(const std::vector<std::int64_t>& t, int x, int y) const
    {
        return t[static_cast<std::size_t>(y * (nx_ + 1) + x)];
    }
    std::int64_t rectSum(const std::vector<std::int64_t>& t, const Rect& r) const
    {
        return r.empty() ? 0 : at(t, r.x1, r.y1) - at(t, r.x0, r.y1) - at(t, r.x1, r.y0) + at(t, r.x0, r.y0);
    }

    int nx_ = 0;
    int ny_ = 0;
    std::vector<std::int64_t> mass_; // (nx + 1) x (ny + 1) summed-area tables
    std::vector<std::int64_t> massX_; // of mass times the cell's x index
    std::vector<std::int64_t> massY_; // of mass times the cell's y index
};

} // namespace penumbra::shadows
