#include "penumbra/shadows/DepthFitTiles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <glm/common.hpp>

namespace penumbra::shadows {
namespace {

// The most raster cells along a side: the footprint's extent over this is the finest cell the placement sees (a
// power of two, so that the raster stays put while the footprint changes within one).
constexpr int kRasterCells = 256;
// Coordinate descent rounds at most; each moves every size by at most one grid step.
constexpr int kDescentRounds = 16;

// One light slot's samples on a raster anchored to a multiple of its cell: mass per cell, rows of nx.
struct Raster {
    glm::vec2 origin{0.0f};
    float cell = 0.0f;
    int nx = 0;
    int ny = 0;
    std::vector<double> mass;
};

int clampedIndex(float at, float origin, float cell, int n)
{
    return std::clamp(static_cast<int>(std::floor((at - origin) / cell)), 0, n - 1);
}

// Spreads an occupancy cell's count evenly over the raster cells it covers inside the raster (the raster's cell where
// it is no larger, the nearest edge cell where it lies outside).
void spread(Raster& r, glm::vec2 lower, float size, double count)
{
    if (size <= r.cell) {
        const glm::vec2 centre = lower + 0.5f * size;
        r.mass[static_cast<std::size_t>(clampedIndex(centre.y, r.origin.y, r.cell, r.ny) * r.nx +
                                        clampedIndex(centre.x, r.origin.x, r.cell, r.nx))] += count;
        return;
    }
    const int per = static_cast<int>(std::lround(size / r.cell));
    const glm::ivec2 first{static_cast<int>(std::lround((lower.x - r.origin.x) / r.cell)),
                           static_cast<int>(std::lround((lower.y - r.origin.y) / r.cell))};
    const int x0 = std::max(first.x, 0), x1 = std::min(first.x + per, r.nx);
    const int y0 = std::max(first.y, 0), y1 = std::min(first.y + per, r.ny);
    if (x0 >= x1 || y0 >= y1) {
        spread(r, lower + 0.5f * size - 0.5f * r.cell, r.cell, count);
        return;
    }
    const double each = count / static_cast<double>((x1 - x0) * (y1 - y0));
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            r.mass[static_cast<std::size_t>(y * r.nx + x)] += each;
}

std::optional<Raster> rasterOf(const DepthHistogram& histogram, std::uint32_t slot)
{
    if (slot >= histogram.occupancy.size() || histogram.occupancy[slot].empty())
        return std::nullopt;
    const std::optional<Bounds> f =
        depthHistogramFootprint(histogram, slot, 0, static_cast<std::uint32_t>(histogram.bins.size()));
    if (!f)
        return std::nullopt;
    const float extent = std::max({f->max.x - f->min.x, f->max.y - f->min.y, 1e-6f});
    Raster r;
    r.cell = std::exp2(std::ceil(std::log2(extent / static_cast<float>(kRasterCells))));
    r.origin = glm::floor(glm::vec2(f->min) / r.cell) * r.cell;
    r.nx = static_cast<int>(std::floor((f->max.x - r.origin.x) / r.cell)) + 1;
    r.ny = static_cast<int>(std::floor((f->max.y - r.origin.y) / r.cell)) + 1;
    r.mass.assign(static_cast<std::size_t>(r.nx * r.ny), 0.0);
    for (const OccupancyGrid& grid : histogram.occupancy[slot])
        for (std::uint32_t y = 0; y < kOccupancyCells; ++y)
            for (std::uint32_t x = 0; x < kOccupancyCells; ++x)
                if (const std::uint32_t n = grid.counts.at(y * kOccupancyCells + x))
                    spread(r, grid.origin + glm::vec2(x, y) * grid.cellSize, grid.cellSize, n);
    return r;
}

// The k x k window of `mass` (cells from x, y; it may reach past the raster, which holds nothing there).
struct Window {
    int x = 0;
    int y = 0;
    double mass = 0.0;
};

class WindowSums {
public:
    explicit WindowSums(const Raster& r, const std::vector<double>& mass) : nx_(r.nx), ny_(r.ny)
    {
        sums_.assign(static_cast<std::size_t>((nx_ + 1) * (ny_ + 1)), 0.0);
        for (int y = 0; y < ny_; ++y)
            for (int x = 0; x < nx_; ++x)
                at(x + 1, y + 1) = mass[static_cast<std::size_t>(y * nx_ + x)] + at(x, y + 1) + at(x + 1, y) - at(x, y);
    }

    double sum(int x, int y, int k) const
    {
        const int x0 = std::clamp(x, 0, nx_), x1 = std::clamp(x + k, 0, nx_);
        const int y0 = std::clamp(y, 0, ny_), y1 = std::clamp(y + k, 0, ny_);
        return at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0);
    }

    // The window that holds the most, the first in row order among equals.
    Window heaviest(int k) const
    {
        Window best{0, 0, -1.0};
        for (int y = 0; y + k <= std::max(ny_, k); ++y)
            for (int x = 0; x + k <= std::max(nx_, k); ++x)
                if (const double s = sum(x, y, k); s > best.mass)
                    best = {x, y, s};
        return best;
    }

private:
    double& at(int x, int y) { return sums_[static_cast<std::size_t>(y * (nx_ + 1) + x)]; }
    double at(int x, int y) const { return sums_[static_cast<std::size_t>(y * (nx_ + 1) + x)]; }

    int nx_;
    int ny_;
    std::vector<double> sums_;
};

void clear(const Raster& r, std::vector<double>& mass, const Window& w, int k)
{
    for (int y = std::max(w.y, 0); y < std::min(w.y + k, r.ny); ++y)
        for (int x = std::max(w.x, 0); x < std::min(w.x + k, r.nx); ++x)
            mass[static_cast<std::size_t>(y * r.nx + x)] = 0.0;
}

class Placement {
public:
    Placement(std::vector<Raster> rasters, const DepthFitTilesInput& input) : rasters_(std::move(rasters)), in_(input)
    {
        for (const Raster& r : rasters_)
            for (const double m : r.mass)
                samples_ += m;
        samples_ /= static_cast<double>(rasters_.size());
    }

    // The raster cells a tile of half size `half` serves along a side.
    int side(const Raster& r, float half) const
    {
        return static_cast<int>(std::floor(2.0f * half * in_.servedShare / r.cell));
    }

    // Each tile put where it holds the most of what the nearer ones left (at `at`'s centres where given); the mean
    // over slots of the sum of the samples' log2 half sizes.
    double cost(const std::vector<float>& halves, const std::vector<std::vector<glm::vec2>>* at,
                std::vector<std::vector<glm::vec2>>* centres) const
    {
        if (centres)
            centres->assign(halves.size(), std::vector<glm::vec2>(rasters_.size()));
        double total = 0.0;
        for (std::size_t s = 0; s < rasters_.size(); ++s) {
            const Raster& r = rasters_[s];
            std::vector<double> mass = r.mass;
            double left = samples(r);
            for (std::size_t c = 0; c < halves.size(); ++c) {
                const int k = side(r, halves[c]);
                if (k < 1)
                    continue;
                const WindowSums sums(r, mass);
                Window w;
                if (at) {
                    const glm::vec2 corner = ((*at)[c][s] - r.origin) / r.cell - 0.5f * static_cast<float>(k);
                    w = {static_cast<int>(std::lround(corner.x)), static_cast<int>(std::lround(corner.y)), 0.0};
                    w.mass = sums.sum(w.x, w.y, k);
                } else {
                    w = sums.heaviest(k);
                }
                total += w.mass * std::log2(static_cast<double>(halves[c]));
                left -= w.mass;
                clear(r, mass, w, k);
                if (centres)
                    (*centres)[c][s] =
                        at ? (*at)[c][s] : r.origin + (glm::vec2(w.x, w.y) + 0.5f * static_cast<float>(k)) * r.cell;
            }
            total += std::max(left, 0.0) * std::log2(static_cast<double>(in_.lastHalfSize));
        }
        return total / static_cast<double>(rasters_.size());
    }

    double samples() const { return samples_; }
    float smallestHalf() const
    {
        float cell = 0.0f;
        for (const Raster& r : rasters_)
            cell = std::max(cell, r.cell);
        return cell / in_.servedShare;
    }

private:
    static double samples(const Raster& r)
    {
        double sum = 0.0;
        for (const double m : r.mass)
            sum += m;
        return sum;
    }

    std::vector<Raster> rasters_;
    DepthFitTilesInput in_;
    double samples_ = 0.0;
};

std::uint32_t gridSteps(const DepthFitTilesInput& input) { return input.stepsPerOctave > 0 ? input.stepsPerOctave : 8; }

// The grid value one step above or below `half` (on the grid).
float gridNeighbour(float half, std::uint32_t steps, bool up)
{
    if (up)
        return half + depthFitStep(half, steps);
    const float below = std::nextafter(half, 0.0f);
    return half - depthFitStep(below, steps);
}

// Powers of two below the last tile's half size down to the smallest a raster can place, sizes not decreasing from
// tile to tile: every combination, each tile's placement shared by the combinations that start alike.
struct CoarseSearch {
    const Placement& placement;
    std::vector<float> candidates;
    std::vector<float> halves;
    std::vector<float> best;
    double bestCost = std::numeric_limits<double>::infinity();

    void search(std::size_t tiles, std::size_t from)
    {
        if (halves.size() == tiles) {
            const double c = placement.cost(halves, nullptr, nullptr);
            if (c < bestCost) {
                bestCost = c;
                best = halves;
            }
            return;
        }
        for (std::size_t i = from; i < candidates.size(); ++i) {
            halves.push_back(candidates[i]);
            search(tiles, i);
            halves.pop_back();
        }
    }
};

} // namespace

DepthFitTiles depthFitTiles(const DepthHistogram& histogram, const DepthFitTilesInput& input)
{
    std::vector<Raster> rasters;
    for (std::uint32_t s = 0; s < histogram.occupancy.size(); ++s) {
        std::optional<Raster> r = rasterOf(histogram, s);
        if (!r)
            return {};
        rasters.push_back(std::move(*r));
    }
    if (rasters.empty() || input.placed == 0 || !(input.lastHalfSize > 0.0f))
        return {};
    const Placement placement(std::move(rasters), input);
    const std::uint32_t steps = gridSteps(input);
    const float smallest = std::min(placement.smallestHalf(), input.lastHalfSize);
    const bool keptFits = input.kept && input.kept->halfSizes.size() == input.placed &&
                          input.kept->centres.size() == input.placed &&
                          std::all_of(input.kept->centres.begin(), input.kept->centres.end(),
                                      [&](const auto& c) { return c.size() == histogram.occupancy.size(); });

    std::vector<float> halves;
    if (keptFits) {
        halves = input.kept->halfSizes;
    } else {
        CoarseSearch coarse{placement, {}, {}, {}};
        for (float h = std::exp2(std::floor(std::log2(std::nextafter(input.lastHalfSize, 0.0f)))); h >= smallest;
             h *= 0.5f)
            coarse.candidates.insert(coarse.candidates.begin(), h);
        if (coarse.candidates.empty())
            coarse.candidates.push_back(std::exp2(std::floor(std::log2(input.lastHalfSize))));
        coarse.search(input.placed, 0);
        halves = coarse.best;
    }
    double cost = placement.cost(halves, nullptr, nullptr);
    for (int round = 0; round < kDescentRounds; ++round) {
        bool moved = false;
        for (std::size_t c = 0; c < halves.size(); ++c)
            for (const bool up : {false, true}) {
                std::vector<float> candidate = halves;
                candidate[c] = gridNeighbour(halves[c], steps, up);
                if (!(candidate[c] >= smallest && candidate[c] < input.lastHalfSize))
                    continue;
                // A relative margin: float noise must not move a size back and forth.
                if (const double c2 = placement.cost(candidate, nullptr, nullptr); c2 < cost - 1e-9 * std::abs(cost)) {
                    cost = c2;
                    halves = std::move(candidate);
                    moved = true;
                }
            }
        if (!moved)
            break;
    }
    DepthFitTiles tiles;
    tiles.halfSizes = halves;
    placement.cost(halves, nullptr, &tiles.centres);
    if (keptFits &&
        placement.cost(input.kept->halfSizes, &input.kept->centres, nullptr) <=
            cost + static_cast<double>(input.toleranceLog2) * placement.samples())
        return *input.kept;
    return tiles;
}

} // namespace penumbra::shadows
