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
// are spread onto one raster about its footprint, and the tiles are the squares that put the samples' texels highest,
// the least mean log2 of the half size of the tile that serves each sample (the geometric mean texel, as
// depthFitPartition's cost; the median would be a step function of the sizes, and the geometric mean also counts the
// near and far tails), averaged over the slots. For given half sizes (shared by the slots) each tile in turn is put
// where it holds the most samples the nearer ones left; the sizes are searched on the grid, powers of two first (half
// sizes not decreasing from tile to tile), then by coordinate descent one grid step at a time; the samples no placed
// tile holds are the last tile's. `kept` stays, sizes and centres, while it costs at most toleranceLog2 more per
// sample; the search then starts from its sizes. Empty where no slot has occupancy grids.
DepthFitTiles depthFitTiles(const DepthHistogram& histogram, const DepthFitTilesInput& input);

} // namespace penumbra::shadows
