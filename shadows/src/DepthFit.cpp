#include "penumbra/shadows/DepthFit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

// The sum of the partition's run costs.
double partitionCost(const RunCosts& runs, std::span<const std::uint32_t> edges)
{
    double sum = 0.0;
    std::vector<double> costs;
    for (std::size_t c = 0; c + 1 < edges.size(); ++c) {
        runs.costsEndingAt(edges[c + 1], edges[c], costs);
        sum += costs.front();
    }
    return sum;
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

    const bool keptHoldsTheSamples = kept.size() == edges.size() && kept.front() <= first && kept.back() >= last &&
                                     kept.back() <= histogram.bins.size() && std::is_sorted(kept.begin(), kept.end());
    if (keptHoldsTheSamples) {
        std::uint64_t samples = 0;
        for (std::uint32_t b = first; b < last; ++b)
            samples += histogram.bins[b].count;
        const double keptCost = partitionCost(runs, kept);
        if (keptCost <= best[cascadeCount - 1][width - 1] + toleranceLog2 * static_cast<double>(samples))
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

float depthFitHalfSize(float required, std::optional<float> kept, std::uint32_t stepsPerOctave, float hysteresisSteps)
{
    if (stepsPerOctave == 0 || !(required > 0.0f))
        return required;
    const float step = depthFitStep(required, stepsPerOctave);
    const float fitted = std::ceil(required / step) * step;
    if (kept && required <= *kept && required > *kept - (1.0f + hysteresisSteps) * depthFitStep(*kept, stepsPerOctave))
        return *kept;
    return fitted;
}

} // namespace penumbra::shadows
