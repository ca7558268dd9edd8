#include "penumbra/shadows/DepthFitTiles.hpp"

#include "penumbra/shadows/OccupancyRaster.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <span>
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

int clampedIndex(float at, float origin, float cell, int n)
{
    return std::clamp(static_cast<int>(std::floor((at - origin) / cell)), 0, n - 1);
}

// Adds `each` to the raster cells [x0, x1) x [y0, y1) in a difference table (rows of nx + 1), which rasterOf sums.
void addRect(std::vector<std::int64_t>& diff, int nx, int x0, int y0, int x1, int y1, std::int64_t each)
{
    const auto at = [nx](int x, int y) { return static_cast<std::size_t>(y * (nx + 1) + x); };
    diff[at(x0, y0)] += each;
    diff[at(x1, y0)] -= each;
    diff[at(x0, y1)] -= each;
    diff[at(x1, y1)] += each;
}

// Spreads an occupancy cell's count evenly over the raster cells it covers inside the raster (the raster's cell where
// it is no larger, the nearest edge cell where it lies outside), into the difference table.
void spread(const OccupancyRaster& r, std::vector<std::int64_t>& diff, glm::vec2 lower, float size, std::int64_t count)
{
    if (size <= r.cell) {
        const glm::vec2 centre = lower + 0.5f * size;
        const int x = clampedIndex(centre.x, r.origin.x, r.cell, r.nx),
                  y = clampedIndex(centre.y, r.origin.y, r.cell, r.ny);
        addRect(diff, r.nx, x, y, x + 1, y + 1, count * kRasterMassUnit);
        return;
    }
    const int per = static_cast<int>(std::lround(size / r.cell));
    const glm::ivec2 first{static_cast<int>(std::lround((lower.x - r.origin.x) / r.cell)),
                           static_cast<int>(std::lround((lower.y - r.origin.y) / r.cell))};
    const int x0 = std::max(first.x, 0), x1 = std::min(first.x + per, r.nx);
    const int y0 = std::max(first.y, 0), y1 = std::min(first.y + per, r.ny);
    if (x0 >= x1 || y0 >= y1) {
        spread(r, diff, lower + 0.5f * size - 0.5f * r.cell, r.cell, count);
        return;
    }
    const std::int64_t area = static_cast<std::int64_t>(x1 - x0) * (y1 - y0);
    addRect(diff, r.nx, x0, y0, x1, y1, (count * kRasterMassUnit + area / 2) / area);
}

std::optional<OccupancyRaster> rasterOf(const DepthHistogram& histogram, std::uint32_t slot)
{
    if (slot >= histogram.occupancy.size() || histogram.occupancy[slot].empty())
        return std::nullopt;
    const std::optional<Bounds> f =
        depthHistogramFootprint(histogram, slot, 0, static_cast<std::uint32_t>(histogram.bins.size()));
    if (!f)
        return std::nullopt;
    const float extent = std::max({f->max.x - f->min.x, f->max.y - f->min.y, 1e-6f});
    OccupancyRaster r;
    r.cell = std::exp2(std::ceil(std::log2(extent / static_cast<float>(kRasterCells))));
    r.origin = glm::floor(glm::vec2(f->min) / r.cell) * r.cell;
    r.nx = static_cast<int>(std::floor((f->max.x - r.origin.x) / r.cell)) + 1;
    r.ny = static_cast<int>(std::floor((f->max.y - r.origin.y) / r.cell)) + 1;
    // Each occupancy cell adds to a rectangle of raster cells: four entries of a difference table, summed once, rather
    // than every cell of the rectangle (a far octave's cell covers thousands).
    std::vector<std::int64_t> diff(static_cast<std::size_t>((r.nx + 1) * (r.ny + 1)), 0);
    for (const OccupancyGrid& grid : histogram.occupancy[slot])
        for (std::uint32_t y = 0; y < kOccupancyCells; ++y)
            for (std::uint32_t x = 0; x < kOccupancyCells; ++x)
                if (const std::uint32_t n = grid.counts.at(y * kOccupancyCells + x))
                    spread(r, diff, grid.origin + glm::vec2(x, y) * grid.cellSize, grid.cellSize, n);
    r.mass.assign(static_cast<std::size_t>(r.nx * r.ny), 0);
    std::vector<std::int64_t> column(static_cast<std::size_t>(r.nx), 0);
    for (int y = 0; y < r.ny; ++y) {
        std::int64_t row = 0;
        for (int x = 0; x < r.nx; ++x) {
            row += diff[static_cast<std::size_t>(y * (r.nx + 1) + x)];
            column[static_cast<std::size_t>(x)] += row;
            r.mass[static_cast<std::size_t>(y * r.nx + x)] = column[static_cast<std::size_t>(x)];
        }
    }
    return r;
}

double samplesOf(std::int64_t mass) { return static_cast<double>(mass) / static_cast<double>(kRasterMassUnit); }

// From the heaviest window, mean shift (Comaniciu and Meer, "Mean Shift: A Robust Approach Toward Feature Space
// Analysis", PAMI 2002): the window moves to be centred on the mean of the samples it holds until it is. Where
// neighbouring windows hold nearly as much (a plateau), which one is heaviest turns on a few samples, and the
// configurations' depth buffers, which differ in their last bits, move a few samples into a neighbouring cell; the
// mean moves only as much as those samples weigh, so every configuration places the tile alike (the parity tests).
RasterWindow centred(const RasterWindowSums::Without& sums, RasterWindow w)
{
    for (int step = 0; step < kShiftSteps; ++step) {
        const glm::ivec2 corner = sums.centredCorner(w.x, w.y, w.k);
        if (corner.x == w.x && corner.y == w.y)
            break;
        w = {corner.x, corner.y, w.k, sums.sum(corner.x, corner.y, w.k)};
    }
    return w;
}

// From the mean-shift window, one cell at a time towards more samples while a move gains more than `decisive`: the
// mean of samples that end at an edge (the near ground at the view's bottom edge) leaves empty cells in the window.
RasterWindow climbed(const RasterWindowSums::Without& sums, RasterWindow w, double decisive)
{
    constexpr std::array<glm::ivec2, 4> kMoves{glm::ivec2(-1, 0), glm::ivec2(1, 0), glm::ivec2(0, -1),
                                               glm::ivec2(0, 1)};
    for (int step = 0; step < 4 * kShiftSteps; ++step) {
        RasterWindow best = w;
        for (const glm::ivec2 move : kMoves) {
            const std::int64_t m = sums.sum(w.x + move.x, w.y + move.y, w.k);
            if (samplesOf(m) > samplesOf(best.mass) + decisive)
                best = {w.x + move.x, w.y + move.y, w.k, m};
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
    Placement(std::vector<OccupancyRaster> rasters, const DepthFitTilesInput& input) : in_(input)
    {
        for (OccupancyRaster& r : rasters) {
            slots_.push_back({r.origin, r.cell, RasterWindowSums(r)});
            samples_ += samplesOf(slots_.back().sums.total());
        }
        samples_ /= static_cast<double>(slots_.size());
    }

    // The raster cells a tile of half size `half` serves along a side.
    int side(float cell, float half) const
    {
        return static_cast<int>(std::floor(2.0f * half * in_.servedShare / cell));
    }

    // Each tile put where it holds the most of what the nearer ones left (at `at`'s centres where given); the sum is
    // the mean over slots.
    Cost cost(const std::vector<float>& halves, const std::vector<std::vector<glm::vec2>>* at,
              std::vector<std::vector<glm::vec2>>* centres)
    {
        if (centres)
            centres->assign(halves.size(), std::vector<glm::vec2>(slots_.size()));
        double total = 0.0;
        std::vector<std::pair<double, double>> served; // log2 half size, samples
        const double lastLog2 = std::log2(static_cast<double>(in_.lastHalfSize));
        for (std::size_t s = 0; s < slots_.size(); ++s) {
            const Slot& slot = slots_[s];
            std::vector<RasterWindow> cleared;
            std::int64_t left = slot.sums.total();
            for (std::size_t c = 0; c < halves.size(); ++c) {
                const int k = side(slot.cell, halves[c]);
                if (k < 1)
                    continue;
                RasterWindow w;
                if (at) {
                    const glm::vec2 corner = ((*at)[c][s] - slot.origin) / slot.cell - 0.5f * static_cast<float>(k);
                    w = {static_cast<int>(std::lround(corner.x)), static_cast<int>(std::lround(corner.y)), k, 0};
                    w.mass = slot.sums.without(cleared).sum(w.x, w.y, k);
                } else {
                    w = placed(s, k, cleared);
                }
                const double mass = samplesOf(w.mass);
                served.emplace_back(std::log2(static_cast<double>(halves[c])), mass);
                total += mass * served.back().first;
                left -= w.mass;
                cleared.push_back(w);
                if (centres)
                    (*centres)[c][s] =
                        at ? (*at)[c][s]
                           : slot.origin + (glm::vec2(w.x, w.y) + 0.5f * static_cast<float>(k)) * slot.cell;
            }
            served.emplace_back(lastLog2, samplesOf(std::max<std::int64_t>(left, 0)));
            total += served.back().second * lastLog2;
        }
        std::sort(served.begin(), served.end());
        double below = 0.0;
        Cost cost{lastLog2, total / static_cast<double>(slots_.size())};
        for (const auto& [log2Half, samples] : served) {
            below += samples;
            if (below >= 0.5 * samples_ * static_cast<double>(slots_.size())) {
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
        for (const Slot& s : slots_)
            cell = std::max(cell, s.cell);
        return cell / in_.servedShare;
    }

private:
    struct Slot {
        glm::vec2 origin;
        float cell;
        RasterWindowSums sums;
    };

    // Where slot s's tile of k cells goes, the earlier tiles' windows cleared; a tile's window depends on nothing
    // else, so the searches, which try many sizes sharing their first tiles, place each such tile once.
    RasterWindow placed(std::size_t s, int k, const std::vector<RasterWindow>& cleared)
    {
        std::vector<int> key{static_cast<int>(s), k};
        for (const RasterWindow& w : cleared)
            key.insert(key.end(), {w.x, w.y, w.k});
        if (const auto found = placedBefore_.find(key); found != placedBefore_.end())
            return found->second;
        const RasterWindowSums::Without sums = slots_[s].sums.without(cleared);
        const double decisive = kDecisiveGain * samplesOf(slots_[s].sums.total());
        const RasterWindow w = climbed(sums, centred(sums, sums.heaviest(k)), decisive);
        placedBefore_.emplace(std::move(key), w);
        return w;
    }

    std::vector<Slot> slots_;
    DepthFitTilesInput in_;
    double samples_ = 0.0;
    std::map<std::vector<int>, RasterWindow> placedBefore_;
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
    Placement& placement;
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
    std::vector<OccupancyRaster> rasters;
    for (std::uint32_t s = 0; s < histogram.occupancy.size(); ++s) {
        std::optional<OccupancyRaster> r = rasterOf(histogram, s);
        if (!r)
            return {};
        rasters.push_back(std::move(*r));
    }
    if (rasters.empty() || input.placed == 0 || !(input.lastHalfSize > 0.0f))
        return {};
    Placement placement(std::move(rasters), input);
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
