#include "penumbra/shadows/DepthFitTiles.hpp"

#include <algorithm>
#include <array>
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
// Mean-shift steps at most from the heaviest window to the one centred on its samples.
constexpr int kShiftSteps = 16;
// The least gain, in bits per sample, for which the descent moves a size. About the optimum the cost is flat, so
// neighbouring sizes nearly tie there, and the configurations' depth buffers, which differ in their last bits, move a
// few samples into a neighbouring cell: a size must win by more than those samples weigh, or the configurations
// would choose differently (the parity tests).
constexpr double kDecisiveGain = 1.0 / 256.0;

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

    // The mean of the cells' x, y (cell centres, in cells) in the window, weighted by `mass`; the window's centre where
    // it holds nothing.
    static glm::dvec2 centroid(const Raster& r, const std::vector<double>& mass, int x, int y, int k)
    {
        glm::dvec2 weighted(0.0);
        double total = 0.0;
        for (int j = std::max(y, 0); j < std::min(y + k, r.ny); ++j)
            for (int i = std::max(x, 0); i < std::min(x + k, r.nx); ++i) {
                const double m = mass[static_cast<std::size_t>(j * r.nx + i)];
                weighted += m * glm::dvec2(i + 0.5, j + 0.5);
                total += m;
            }
        return total > 0.0 ? weighted / total : glm::dvec2(x, y) + 0.5 * k;
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

// From the heaviest window, mean shift (Comaniciu and Meer, "Mean Shift: A Robust Approach Toward Feature Space
// Analysis", PAMI 2002): the window moves to be centred on the mean of the samples it holds until it is. Where
// neighbouring windows hold nearly as much (a plateau), which one is heaviest turns on a few samples, and the
// configurations' depth buffers, which differ in their last bits, move a few samples into a neighbouring cell; the
// mean moves only as much as those samples weigh, so every configuration places the tile alike (the parity tests).
Window centred(const Raster& r, const std::vector<double>& mass, const WindowSums& sums, Window w, int k)
{
    for (int step = 0; step < kShiftSteps; ++step) {
        const glm::dvec2 mean = WindowSums::centroid(r, mass, w.x, w.y, k);
        const glm::ivec2 corner(static_cast<int>(std::floor(mean.x - 0.5 * k + 0.5)),
                                static_cast<int>(std::floor(mean.y - 0.5 * k + 0.5)));
        if (corner.x == w.x && corner.y == w.y)
            break;
        w = {corner.x, corner.y, sums.sum(corner.x, corner.y, k)};
    }
    return w;
}

// From the mean-shift window, one cell at a time towards more samples while a move gains more than `decisive`: the
// mean of samples that end at an edge (the near ground at the view's bottom edge) leaves empty cells in the window.
Window climbed(const WindowSums& sums, Window w, int k, double decisive)
{
    constexpr std::array<glm::ivec2, 4> kMoves{glm::ivec2(-1, 0), glm::ivec2(1, 0), glm::ivec2(0, -1),
                                               glm::ivec2(0, 1)};
    for (int step = 0; step < 4 * kShiftSteps; ++step) {
        Window best = w;
        for (const glm::ivec2 move : kMoves) {
            const double m = sums.sum(w.x + move.x, w.y + move.y, k);
            if (m > best.mass + decisive)
                best = {w.x + move.x, w.y + move.y, m};
        }
        if (best.x == w.x && best.y == w.y)
            break;
        w = best;
    }
    return w;
}

// What a placement costs: first the log2 half size of the tile that serves the median sample (the measure,
// texels per metre on screen, is a median), then the sum over samples of log2 of their tile's half size (the
// geometric mean texel, depthFitPartition's cost), which decides between sizes with the same median and weighs the
// tails; both over every slot's samples.
struct Cost {
    double median = 0.0;
    double sum = 0.0;

    // Better by more than `margin` in the sum, or by a smaller median.
    bool beats(const Cost& other, double margin) const
    {
        return median < other.median || (median == other.median && sum < other.sum - margin);
    }
};

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

    // Each tile put where it holds the most of what the nearer ones left (at `at`'s centres where given); the sum is
    // the mean over slots.
    Cost cost(const std::vector<float>& halves, const std::vector<std::vector<glm::vec2>>* at,
              std::vector<std::vector<glm::vec2>>* centres) const
    {
        if (centres)
            centres->assign(halves.size(), std::vector<glm::vec2>(rasters_.size()));
        double total = 0.0;
        std::vector<std::pair<double, double>> served; // log2 half size, samples
        const double lastLog2 = std::log2(static_cast<double>(in_.lastHalfSize));
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
                    w = climbed(sums, centred(r, mass, sums, sums.heaviest(k), k), k, kDecisiveGain * samples(r));
                }
                served.emplace_back(std::log2(static_cast<double>(halves[c])), w.mass);
                total += w.mass * served.back().first;
                left -= w.mass;
                clear(r, mass, w, k);
                if (centres)
                    (*centres)[c][s] =
                        at ? (*at)[c][s] : r.origin + (glm::vec2(w.x, w.y) + 0.5f * static_cast<float>(k)) * r.cell;
            }
            served.emplace_back(lastLog2, std::max(left, 0.0));
            total += served.back().second * lastLog2;
        }
        std::sort(served.begin(), served.end());
        double below = 0.0;
        Cost cost{lastLog2, total / static_cast<double>(rasters_.size())};
        for (const auto& [log2Half, samples] : served) {
            below += samples;
            if (below >= 0.5 * samples_ * static_cast<double>(rasters_.size())) {
                cost.median = log2Half;
                break;
            }
        }
        return cost;
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
    Cost bestCost{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};

    void search(std::size_t tiles, std::size_t from)
    {
        if (halves.size() == tiles) {
            const Cost c = placement.cost(halves, nullptr, nullptr);
            if (c.beats(bestCost, 0.0)) {
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
    Cost cost = placement.cost(halves, nullptr, nullptr);
    for (int round = 0; round < kDescentRounds; ++round) {
        bool moved = false;
        for (std::size_t c = 0; c < halves.size(); ++c)
            for (const bool up : {false, true}) {
                std::vector<float> candidate = halves;
                candidate[c] = gridNeighbour(halves[c], steps, up);
                if (!(candidate[c] >= smallest && candidate[c] < input.lastHalfSize))
                    continue;
                if (const Cost c2 = placement.cost(candidate, nullptr, nullptr);
                    c2.beats(cost, kDecisiveGain * placement.samples())) {
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
    if (keptFits) {
        const Cost kept = placement.cost(input.kept->halfSizes, &input.kept->centres, nullptr);
        const auto tolerance = static_cast<double>(input.toleranceLog2);
        if (kept.median <= cost.median + tolerance && kept.sum <= cost.sum + tolerance * placement.samples())
            return *input.kept;
    }
    return tiles;
}

} // namespace penumbra::shadows
