#pragma once

#include "penumbra/shadows/Bounds.hpp"
#include "penumbra/shadows/CascadeSplits.hpp"
#include "penumbra/shadows/DirectionalShadowUniforms.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace penumbra::shadows {

// The view depths of the surfaces the camera sees, nearest and farthest (a reduction of the depth prepass).
struct ViewDepthRange {
    float nearDepth = 0.0f;
    float farDepth = 0.0f;

    bool operator==(const ViewDepthRange&) const = default;
};

// The grid step of view depth `depth` with `stepsPerOctave` steps per power of two: 2^floor(log2 depth) / steps,
// so that a step is between 1 / steps and 2 / steps of the depth itself.
float depthFitStep(float depth, std::uint32_t stepsPerOctave);

// The depth fit's histogram of the visible view depths (shaders/depth_reduction.comp): bins on depthFitStep's grid
// at 8 steps per power of two over the 16 octaves below the shadow distance, each with its samples' count and, per
// shadowed directional light, their light-space footprint. Sample distribution shadow maps (Lauritzen, Salvi and
// Lefohn, I3D 2011) place the splits from such a histogram (section 4.1) and fit each cascade to the light-space
// bounds of the samples in its partition (section 4.2), which is where most of their gain comes from.
inline constexpr std::uint32_t kDepthHistogramStepsPerOctave = 8;
inline constexpr std::uint32_t kDepthHistogramBins = 16 * kDepthHistogramStepsPerOctave;

struct DepthHistogramBin {
    std::uint32_t count = 0;
    // Per light slot: min x, min y, max x, max y in the light's basis (LightBasis::toLight) of the bin's samples.
    std::array<glm::vec4, maxShadowedDirectionalLights> footprints{};
};

// The reduction's light-space occupancy grids, the finer light-space information the tiles are placed with
// (depthFitTiles): per shadowed light and per octave of view depth, the last kOccupancyOctaves octaves below the
// shadow distance (nearer samples count in the first), kOccupancyCells x kOccupancyCells counts of the samples in each
// cell of a square grid about the camera. A cell is 1/8 of the octave's near depth, so the grid reaches twice the
// octave's far depth from the camera on each side (any sample within a 2 x 2 field of view's tangents of that
// depth; farther ones count in the edge cells): cells as fine as the tiles that serve those depths need.
inline constexpr std::uint32_t kOccupancyCells = 64;
inline constexpr std::uint32_t kOccupancyOctaves = 8;

struct OccupancyGrid {
    glm::vec2 origin{0.0f}; // light-space x, y of cell (0, 0)'s lower corner, a multiple of cellSize
    float cellSize = 0.0f; // a power of two
    std::vector<std::uint32_t> counts; // kOccupancyCells^2, row after row (y major)
};

// The occupancy grid of octave `octave` (0 to kOccupancyOctaves - 1) of a histogram starting at `firstOctave`, placed
// about the camera's light-space x, y on its own cell grid, so that it stays put while the camera moves within a
// cell; counts empty.
OccupancyGrid occupancyGridAbout(int firstOctave, std::uint32_t octave, glm::vec2 camera);
// The occupancy octave of histogram bin `bin`: the shader's, on the CPU.
std::uint32_t occupancyOctave(std::uint32_t bin);

struct DepthHistogram {
    int firstOctave = 0; // bin 0 starts at 2^firstOctave; nearer samples are counted in it
    std::vector<DepthHistogramBin> bins; // kDepthHistogramBins
    // Per light slot: the direction the footprints were measured along (the plan's light in that slot).
    std::vector<glm::vec3> lightDirections;
    // Per light slot, the occupancy grids (kOccupancyOctaves); empty where none were reduced.
    std::vector<std::vector<OccupancyGrid>> occupancy;
};

// ceil(log2 shadowFar) - 16: the histogram's last bin ends at or past the shadow distance.
int depthHistogramFirstOctave(float shadowFar);
// Where bin `bin` starts: 2^(firstOctave + bin / 8) (1 + (bin % 8) / 8); bin kDepthHistogramBins is the last's end.
float depthHistogramBinStart(int firstOctave, std::uint32_t bin);
// The bin of view depth `depth`, clamped to the histogram: the shader's binning, on the CPU.
std::uint32_t depthHistogramBin(int firstOctave, float depth);
// The start of the first bin with samples and the end of the last (2^firstOctave where bin 0 has samples, which may
// be nearer); nullopt where no bin has any.
std::optional<ViewDepthRange> depthHistogramRange(const DepthHistogram& histogram);
// The light-space footprint of slot `slot`'s samples in bins [first, last) (z 0); nullopt where they have none.
std::optional<Bounds> depthHistogramFootprint(const DepthHistogram& histogram, std::uint32_t slot, std::uint32_t first,
                                              std::uint32_t last);

// What a depth-fit plan keeps for the next frame's: its partition of the histogram and its tiles' half sizes.
struct DepthFitKept {
    std::vector<std::uint32_t> edges; // cascade c holds bins [edges[c], edges[c + 1])
    std::vector<float> halfSizes; // per cascade
    // Tiles placed over the occupancy grids (depthFitTiles): per cascade but the last, per histogram light slot, the
    // centre of the square it serves; empty otherwise.
    std::vector<std::vector<glm::vec2>> centres;

    bool operator==(const DepthFitKept&) const = default;
};

// The partition of the histogram's bins into `cascadeCount` runs that puts the visible samples' texels highest: the
// least sum over samples of log2 of the light-space extent of the tile that serves them (the larger side of the
// footprint over slots [0, lightSlots); the run's far depth where lightSlots is 0), so the geometric mean of the
// samples' texel sizes is least (SDSM's partitions, section 4.1, optimized for the texel size rather than log or
// k-means spaced). First exactly, by dynamic programming over the bins with samples, with each sample served by its own
// run's tile; then, with footprints, refined by coordinate descent for map-based selection, which serves a sample by
// the first tile that holds it: a near tile also serves the far samples inside it (their share estimated from the bins'
// footprints). The result's edges run from the first bin with samples to one past the last. `kept` (the last frame's
// edges) stays while it still holds every sample and its cost is within `toleranceLog2` per sample of the result's:
// hysteresis, so that depths that barely move keep the splits.
std::vector<std::uint32_t> depthFitPartition(const DepthHistogram& histogram, std::uint32_t cascadeCount,
                                             std::uint32_t lightSlots, std::span<const std::uint32_t> kept,
                                             float toleranceLog2);

// The splits of a partition: edge c's bin start for the inner splits, the partition's first and last edges for the
// outer ones (bin 0's start taken as the camera's near plane), each clamped to [cameraNear, shadowFar] with
// shadowFar = min(maxDistance, cameraFar), in order.
CascadeSplits depthFitSplits(const DepthHistogram& histogram, std::span<const std::uint32_t> edges, float cameraNear,
                             float cameraFar, float maxDistance);

// The half size of a depth-fit tile: `required` (closeFitHalfSize of its footprint) ceiled onto depthFitStep's grid
// of light-space size at `stepsPerOctave` steps per power of two; `kept` (the last frame's) while required is more than
// 1 + hysteresisSteps of its steps below it and at most kept, so the texel size, and with it every texel, holds still
// while the footprint barely changes. `mayFallShort` (every cascade but the last): kept also while required is at
// most half of hysteresisSteps steps above it, for map-based selection serves the few samples past a tile's edge from
// the next tile; without it a footprint fitted just below a grid line moves every texel of its tile when it grows
// by a texel. stepsPerOctave 0: required, unquantized.
float depthFitHalfSize(float required, std::optional<float> kept, std::uint32_t stepsPerOctave, float hysteresisSteps,
                       bool mayFallShort = false);

} // namespace penumbra::shadows
