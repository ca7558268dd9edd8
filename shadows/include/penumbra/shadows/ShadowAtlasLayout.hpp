#pragma once

#include "penumbra/rhi/CommandList.hpp"
#include "penumbra/shadows/TileTexelBounds.hpp"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

namespace penumbra::shadows {

inline constexpr std::uint32_t maxAtlasTiles = 64;

// How many tiles a side an atlas of n tiles is cut into. PowersOfTwo: 1 for one tile, 2 for up to 4, 4 for up to
// 16, 8 for up to 64. WithThree also cuts 3 x 3 for 5 to 9 tiles (the design documents' "Dynamic Tiling": Catlike
// Coding, "Spotlight Shadows", so that at least half of the atlas is in use): each tile gets 16/9 of the texels of a
// 4 x 4 cut, and the atlasSize % 3 texels at the right and bottom edges belong to no tile.
enum class AtlasSplits : std::uint8_t { PowersOfTwo, WithThree };

// A square atlas cut into split x split square tiles of atlasSize / split texels (rounded down). Tile i sits at
// column i % split, row i / split, rows counted from the TOP as rhi::Viewport and texture v do. Used by the
// directional atlas (lights x cascades) and the static local atlas (up to 64); the realtime local atlas gives each
// light a tile of its own size (ShadowAtlasPacker).
class ShadowAtlasLayout {
public:
    // Throws rhi::Error when tileCount > maxAtlasTiles or atlasSize is not a multiple of a power-of-two split.
    ShadowAtlasLayout(std::uint32_t atlasSize, std::uint32_t tileCount, AtlasSplits splits = AtlasSplits::PowersOfTwo);

    // Texels per side of the atlas.
    std::uint32_t atlasSize() const { return atlasSize_; }
    // Tiles in use.
    std::uint32_t tileCount() const { return tileCount_; }
    // Tiles per side: 1, 2, 3, 4 or 8.
    std::uint32_t split() const { return split_; }
    // Texels per side of a tile, rounded down for a split of 3.
    std::uint32_t tileSize() const { return atlasSize_ / split_; }

    // Column and row of a tile, in tiles.
    glm::uvec2 tileCoordinates(std::uint32_t tile) const;
    // Top-left texel of a tile.
    glm::uvec2 tileOffset(std::uint32_t tile) const;
    // First and last texel of a tile: the texels its filter taps may read.
    TileTexelBounds tileTexelBounds(std::uint32_t tile) const;
    // The viewport of a tile, rows counted from the top.
    rhi::Viewport viewport(std::uint32_t tile) const;
    // Maps a tile's texture coordinates (u, v in [0, 1], depth) to the atlas's; depth passes through.
    glm::mat4 tileToAtlas(std::uint32_t tile) const;

private:
    std::uint32_t atlasSize_;
    std::uint32_t tileCount_;
    std::uint32_t split_;
};

// Tile of cascade `cascade` of shadowed directional light `light`: light * cascadeCount + cascade.
constexpr std::uint32_t directionalTileIndex(std::uint32_t light, std::uint32_t cascade, std::uint32_t cascadeCount)
{
    return light * cascadeCount + cascade;
}

} // namespace penumbra::shadows
