#pragma once

#include "penumbra/shadows/DepthFit.hpp"

#include <cstdint>
#include <vector>
#include <glm/vec2.hpp>

namespace penumbra::shadows {

// The depth fit's tiles but the last, placed over the reduction's occupancy grids: per cascade a half size on
// depthFitStep's grid and, per histogram light slot, the centre of the square it serves.
struct DepthFitTiles {
    std::vector<float> halfSizes; // per placed cascade
    std::vector<std::vector<glm::vec2>> centres; // per placed cascade, per histogram light slot

    bool operator==(const DepthFitTiles&) const = default;
};

struct DepthFitTilesInput {
    std::uint32_t placed = 0; // the cascades to place: every one but the last
    float lastHalfSize = 0.0f; // the last tile's, which holds every sample
    // The share of a tile's half size about its centre whose samples it serves: map-based selection leaves out a
    // margin of filter texels at the edge.
    float servedShare = 1.0f;
    std::uint32_t stepsPerOctave = 8; // depthFitStep's grid of the half sizes (0: 8, the search's grid)
    // The last frame's tiles stay while they cost at most this much more per sample in log2 than the search's.
    float toleranceLog2 = 0.0f;
    const DepthFitTiles* kept = nullptr;
};

// Map-based selection serves a sample by the first tile that holds it, whatever its depth, so the tiles are placed
// around clusters of the samples in light space rather than around runs of depth: each light slot's occupancy grids
// are spread onto one raster about its footprint. For given half sizes (shared by the slots) each tile in turn goes to
// the window that holds the most of what the tiles before it left, then to the one centred on those samples (mean
// shift) and towards more of them while a move gains more than 1/256 of the samples, so that the few samples the
// configurations' depth buffers put in a neighbouring cell place no tile differently; the samples no placed tile
// holds are the last tile's. The cost is first the log2 half size of the tile that serves the median sample (the
// issue's measure is the median texel density on screen), then the samples' mean log2 half size (the geometric mean
// texel, depthFitPartition's cost: it chooses among sizes with the same median and weighs the tails). The sizes are
// searched on the grid, powers of two first (half sizes not decreasing from tile to tile), then by coordinate descent
// one grid step at a time, a step taken only for a gain above 1/256 bit per sample. `kept` stays, sizes and centres,
// while its median is at most toleranceLog2 larger and its mean log2 at most toleranceLog2 more per sample; the
// search then starts from its sizes instead of the powers of two. Empty where a slot has no occupancy grids.
DepthFitTiles depthFitTiles(const DepthHistogram& histogram, const DepthFitTilesInput& input);

} // namespace penumbra::shadows
