#include "penumbra/shadows/DepthFit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <glm/common.hpp>

namespace penumbra::shadows {
namespace {

// The bins with samples: [first, last).
struct Occupied {
    std::uint32_t first = 0;
    std::uint32_t last = 0;
};

std::optional<Occupied> occupied(const DepthHistogram& histogram)
{
    std::optional<Occupied> o;
    for (std::uint32_t b = 0; b < histogram.bins.size(); ++b)
        if (histogram.bins[b].count > 0) {
            if (!o)
                o = Occupied{b, b + 1};
            o->last = b + 1;
        }
    return o;
}

// The union of two footprints (min x, min y, max x, max y; empty: min > max).
glm::vec4 unite(glm::vec4 a, glm::vec4 b)
{
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.z, b.z), std::max(a.w, b.w)};
}

constexpr glm::vec4 kNoFootprint{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                                 -std::numeric_limits<float>::max(), -std::numeric_limits<float>::max()};

// The cost of runs [i, j) for every i <= j at a fixed j, built by growing the run backwards from j.
class RunCosts {
public:
    RunCosts(const DepthHistogram& histogram, std::uint32_t lightSlots) : histogram_(histogram), slots_(lightSlots) {}

    // costs[i - offset] for i in [offset, j].
    void costsEndingAt(std::uint32_t j, std::uint32_t offset, std::vector<double>& costs) const
    {
        costs.assign(j - offset + 1, 0.0);
        std::array<glm::vec4, maxShadowedDirectionalLights> footprints;
        footprints.fill(kNoFootprint);
        std::uint64_t count = 0;
        const float farDepth = depthHistogramBinStart(histogram_.firstOctave, j);
        for (std::uint32_t i = j; i-- > offset;) {
            const DepthHistogramBin& bin = histogram_.bins[i];
            count += bin.count;
            float extent = slots_ == 0 ? farDepth : 0.0f;
            for (std::uint32_t s = 0; s < slots_; ++s) {
                if (bin.count > 0)
                    footprints[s] = unite(footprints[s], bin.footprints[s]);
                const glm::vec4 f = footprints[s];
                if (f.x <= f.z)
                    extent = std::max(extent, std::max(f.z - f.x, f.w - f.y));
            }
            // A floor for runs whose samples lie on a line or a point: a thousandth of their depth.
            extent = std::max(extent, 1e-3f * farDepth);
            costs[i - offset] = count == 0 ? 0.0 : static_cast<double>(count) * std::log2(static_cast<double>(extent));
        }
    }

private:
    const DepthHistogram& histogram_;
    std::uint32_t slots_;
};

// The share of [lo, hi] inside [a, b]; a degenerate [lo, hi] (samples on a line) counts whole or not at all.
float depthFitOverlapShare(float lo, float hi, float a, float b)
{
    if (!(hi > lo))
        return lo >= a && lo <= b ? 1.0f : 0.0f;
    return std::max(0.0f, std::min(hi, b) - std::max(lo, a)) / (hi - lo);
}

// A cascade's tile as the cost sees it, per light slot: the square about its samples' footprint, with the half size
// the largest any slot needs (every light's tile of a cascade has one size); none where the run has no samples.
struct MappedTile {
    std::array<glm::vec2, maxShadowedDirectionalLights> centres{};
    float half = 0.0f;
    bool holdsSamples = false;
};

// The cost of a partition as map-based selection serves the samples (CascadeSelection.hpp): a sample takes the first
// tile that holds it, so a nearer tile gives its texels to the far samples inside it. The histogram keeps only each
// bin's footprint, so its samples are taken as spread evenly over it: the share a nearer tile holds is the footprint's
// area inside the tile's square, each nearer tile taking its share of what the ones before left. Per sample the
// log2 of its tile's extent, averaged over the light slots (each light selects in its own tiles).
double mappedPartitionCost(const DepthHistogram& histogram, std::span<const std::uint32_t> edges,
                           std::uint32_t lightSlots)
{
    std::vector<MappedTile> tiles(edges.size() - 1);
    for (std::size_t c = 0; c < tiles.size(); ++c)
        for (std::uint32_t s = 0; s < lightSlots; ++s)
            if (const std::optional<Bounds> f = depthHistogramFootprint(histogram, s, edges[c], edges[c + 1])) {
                const glm::vec3 extent = f->max - f->min;
                tiles[c].centres[s] = 0.5f * glm::vec2(f->min + f->max);
                // RunCosts' floor: a thousandth of the run's far depth.
                const float floor = 0.5e-3f * depthHistogramBinStart(histogram.firstOctave, edges[c + 1]);
                tiles[c].half = std::max({tiles[c].half, 0.5f * std::max(extent.x, extent.y), floor});
                tiles[c].holdsSamples = true;
            }
    double sum = 0.0;
    for (std::size_t c = 0; c < tiles.size(); ++c)
        for (std::uint32_t b = edges[c]; b < edges[c + 1]; ++b) {
            const DepthHistogramBin& bin = histogram.bins[b];
            if (bin.count == 0)
                continue;
            double binCost = 0.0;
            for (std::uint32_t s = 0; s < lightSlots; ++s) {
                const glm::vec4 f = bin.footprints[s];
                double left = 1.0;
                for (std::size_t near = 0; near < c; ++near) {
                    if (!tiles[near].holdsSamples)
                        continue;
                    const glm::vec2 centre = tiles[near].centres[s];
                    const float half = tiles[near].half;
                    const double share = depthFitOverlapShare(f.x, f.z, centre.x - half, centre.x + half) *
                                         depthFitOverlapShare(f.y, f.w, centre.y - half, centre.y + half);
                    binCost += left * share * std::log2(2.0 * half);
                    left *= 1.0 - share;
                }
                binCost += left * std::log2(2.0 * tiles[c].half);
            }
            sum += static_cast<double>(bin.count) * binCost / static_cast<double>(lightSlots);
        }
    return sum;
}

// The partition's cost: mappedPartitionCost where the histogram has footprints, else the sum of its band costs.
double partitionCost(const DepthHistogram& histogram, const RunCosts& runs, std::span<const std::uint32_t> edges,
                     std::uint32_t lightSlots)
{
    if (lightSlots > 0)
        return mappedPartitionCost(histogram, edges, lightSlots);
    double sum = 0.0;
    std::vector<double> costs;
    for (std::size_t c = 0; c + 1 < edges.size(); ++c) {
        runs.costsEndingAt(edges[c + 1], edges[c], costs);
        sum += costs.front();
    }
    return sum;
}

// Coordinate descent on the mapped cost from `edges`: each inner edge in turn moves to the place between its
// neighbours that costs least, until no move gains (at most kPasses rounds). The bands' optimum (the dynamic
// programme's) is a good start: map-based selection mostly moves splits nearer, where a near tile's samples gain most.
std::vector<std::uint32_t> descendMappedCost(const DepthHistogram& histogram, std::vector<std::uint32_t> edges,
                                             std::uint32_t lightSlots)
{
    constexpr int kPasses = 8;
    double best = mappedPartitionCost(histogram, edges, lightSlots);
    for (int pass = 0; pass < kPasses; ++pass) {
        bool moved = false;
        for (std::size_t i = 1; i + 1 < edges.size(); ++i)
            for (std::uint32_t at = edges[i - 1] + 1; at < edges[i + 1]; ++at) {
                std::vector<std::uint32_t> candidate = edges;
                candidate[i] = at;
                const double cost = mappedPartitionCost(histogram, candidate, lightSlots);
                // A relative margin: float noise must not move an edge back and forth.
                if (cost < best - 1e-9 * std::abs(best)) {
                    best = cost;
                    edges = std::move(candidate);
                    moved = true;
                }
            }
        if (!moved)
            break;
    }
    // The dynamic programme's rule for ties: a run starts at its first bin with samples, not in the empty bins before.
    for (std::size_t i = 1; i + 1 < edges.size(); ++i)
        while (edges[i] + 1 < edges[i + 1] && histogram.bins[edges[i]].count == 0)
            ++edges[i];
    return edges;
}

} // namespace

float depthFitStep(float depth, std::uint32_t stepsPerOctave)
{
    return std::exp2(std::floor(std::log2(depth))) / static_cast<float>(stepsPerOctave);
}

int depthHistogramFirstOctave(float shadowFar)
{
    return static_cast<int>(std::ceil(std::log2(shadowFar))) -
           static_cast<int>(kDepthHistogramBins / kDepthHistogramStepsPerOctave);
}

float depthHistogramBinStart(int firstOctave, std::uint32_t bin)
{
    const int octave = firstOctave + static_cast<int>(bin / kDepthHistogramStepsPerOctave);
    const float fraction = static_cast<float>(bin % kDepthHistogramStepsPerOctave) / kDepthHistogramStepsPerOctave;
    return std::ldexp(1.0f + fraction, octave);
}

std::uint32_t depthHistogramBin(int firstOctave, float depth)
{
    if (!(depth > 0.0f))
        return 0;
    int exponent = 0;
    // depth = mantissa 2^exponent with mantissa in [0.5, 1): octave exponent - 1, step floor((2 mantissa - 1) 8).
    const float mantissa = std::frexp(depth, &exponent);
    const int octave = exponent - 1 - firstOctave;
    const int step = static_cast<int>((2.0f * mantissa - 1.0f) * kDepthHistogramStepsPerOctave);
    const int bin = octave * static_cast<int>(kDepthHistogramStepsPerOctave) + step;
    return static_cast<std::uint32_t>(std::clamp(bin, 0, static_cast<int>(kDepthHistogramBins) - 1));
}

OccupancyGrid occupancyGridAbout(int firstOctave, std::uint32_t octave, glm::vec2 camera)
{
    const int near = firstOctave +
                     static_cast<int>(kDepthHistogramBins / kDepthHistogramStepsPerOctave - kOccupancyOctaves + octave);
    OccupancyGrid grid;
    grid.cellSize = std::ldexp(1.0f, near - 3);
    grid.origin = (glm::floor(camera / grid.cellSize) - 0.5f * static_cast<float>(kOccupancyCells)) * grid.cellSize;
    return grid;
}

std::uint32_t occupancyOctave(std::uint32_t bin)
{
    const std::uint32_t skipped = kDepthHistogramBins / kDepthHistogramStepsPerOctave - kOccupancyOctaves;
    return std::max(bin / kDepthHistogramStepsPerOctave, skipped) - skipped;
}

std::optional<ViewDepthRange> depthHistogramRange(const DepthHistogram& histogram)
{
    const std::optional<Occupied> o = occupied(histogram);
    if (!o)
        return std::nullopt;
    return ViewDepthRange{depthHistogramBinStart(histogram.firstOctave, o->first),
                          depthHistogramBinStart(histogram.firstOctave, o->last)};
}

std::optional<Bounds> depthHistogramFootprint(const DepthHistogram& histogram, std::uint32_t slot, std::uint32_t first,
                                              std::uint32_t last)
{
    glm::vec4 f = kNoFootprint;
    last = std::min<std::uint32_t>(last, static_cast<std::uint32_t>(histogram.bins.size()));
    for (std::uint32_t b = first; b < last; ++b)
        if (histogram.bins[b].count > 0)
            f = unite(f, histogram.bins[b].footprints.at(slot));
    if (!(f.x <= f.z && f.y <= f.w))
        return std::nullopt;
    return Bounds{{f.x, f.y, 0.0f}, {f.z, f.w, 0.0f}};
}

std::vector<std::uint32_t> depthFitPartition(const DepthHistogram& histogram, std::uint32_t cascadeCount,
                                             std::uint32_t lightSlots, std::span<const std::uint32_t> kept,
                                             float toleranceLog2)
{
    const std::optional<Occupied> o = occupied(histogram);
    if (!o || cascadeCount == 0)
        return {};
    const RunCosts runs(histogram, lightSlots);
    // best[c][j]: the least cost of bins [first, j) in c + 1 runs; from[c][j]: where its last run starts.
    const std::uint32_t first = o->first, last = o->last;
    const std::size_t width = last - first + 1;
    std::vector<std::vector<double>> best(cascadeCount, std::vector<double>(width, 0.0));
    std::vector<std::vector<std::uint32_t>> from(cascadeCount, std::vector<std::uint32_t>(width, first));
    std::vector<double> costs;
    for (std::uint32_t j = first; j <= last; ++j) {
        runs.costsEndingAt(j, first, costs);
        best[0][j - first] = costs[0];
        for (std::uint32_t c = 1; c < cascadeCount; ++c) {
            double least = std::numeric_limits<double>::infinity();
            std::uint32_t start = first;
            // Ties go to the later start: no run is left empty where a split costs nothing more.
            for (std::uint32_t i = first; i <= j; ++i) {
                const double cost = best[c - 1][i - first] + costs[i - first];
                if (cost <= least) {
                    least = cost;
                    start = i;
                }
            }
            best[c][j - first] = least;
            from[c][j - first] = start;
        }
    }
    std::vector<std::uint32_t> edges(cascadeCount + 1);
    edges[cascadeCount] = last;
    for (std::uint32_t c = cascadeCount - 1; c > 0; --c)
        edges[c] = from[c][edges[c + 1] - first];
    edges[0] = first;
    if (lightSlots > 0)
        edges = descendMappedCost(histogram, std::move(edges), lightSlots);

    const bool keptHoldsTheSamples = kept.size() == edges.size() && kept.front() <= first && kept.back() >= last &&
                                     kept.back() <= histogram.bins.size() && std::is_sorted(kept.begin(), kept.end());
    if (keptHoldsTheSamples) {
        std::uint64_t samples = 0;
        for (std::uint32_t b = first; b < last; ++b)
            samples += histogram.bins[b].count;
        const double keptCost = partitionCost(histogram, runs, kept, lightSlots);
        if (keptCost <=
            partitionCost(histogram, runs, edges, lightSlots) + toleranceLog2 * static_cast<double>(samples))
            return std::vector<std::uint32_t>(kept.begin(), kept.end());
    }
    return edges;
}

CascadeSplits depthFitSplits(const DepthHistogram& histogram, std::span<const std::uint32_t> edges, float cameraNear,
                             float cameraFar, float maxDistance)
{
    const float shadowFar = std::max(std::min(maxDistance, cameraFar), cameraNear);
    CascadeSplits splits;
    splits.count = static_cast<std::uint32_t>(edges.size() - 1);
    for (std::size_t c = 0; c < edges.size(); ++c) {
        const float start =
            c == 0 && edges[c] == 0 ? cameraNear : depthHistogramBinStart(histogram.firstOctave, edges[c]);
        const float lower = c == 0 ? cameraNear : splits.distances[c - 1];
        splits.distances[c] = std::clamp(start, lower, shadowFar);
    }
    return splits;
}

float depthFitHalfSize(float required, std::optional<float> kept, std::uint32_t stepsPerOctave, float hysteresisSteps,
                       bool mayFallShort)
{
    if (stepsPerOctave == 0 || !(required > 0.0f))
        return required;
    const float step = depthFitStep(required, stepsPerOctave);
    const float fitted = std::ceil(required / step) * step;
    if (kept) {
        const float keptStep = depthFitStep(*kept, stepsPerOctave);
        const float largest = *kept + (mayFallShort ? 0.5f * hysteresisSteps * keptStep : 0.0f);
        if (required <= largest && required > *kept - (1.0f + hysteresisSteps) * keptStep)
            return *kept;
    }
    return fitted;
}

} // namespace penumbra::shadows
