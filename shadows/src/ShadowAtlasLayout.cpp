#include "penumbra/shadows/ShadowAtlasLayout.hpp"

#include "penumbra/shadows/AtlasMatrix.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::shadows {

namespace {

std::uint32_t splitFor(std::uint32_t tileCount, AtlasSplits splits)
{
    if (tileCount <= 1)
        return 1;
    if (tileCount <= 4)
        return 2;
    if (tileCount <= 9 && splits == AtlasSplits::WithThree)
        return 3;
    return tileCount <= 16 ? 4 : 8;
}

} // namespace

ShadowAtlasLayout::ShadowAtlasLayout(std::uint32_t atlasSize, std::uint32_t tileCount, AtlasSplits splits)
    : atlasSize_(atlasSize), tileCount_(tileCount), split_(splitFor(tileCount, splits))
{
    if (tileCount > maxAtlasTiles)
        throw rhi::Error(fmt::format("shadow atlas: {} tiles, allowed 0..{}", tileCount, maxAtlasTiles));
    // A split of 3 rounds the tile size down (the documents' choice); a power of two must divide the size exactly.
    if (atlasSize < split_ || (split_ != 3 && atlasSize % split_ != 0))
        throw rhi::Error(
            fmt::format("shadow atlas: size {} cannot be split into {} x {} tiles", atlasSize, split_, split_));
}

glm::uvec2 ShadowAtlasLayout::tileCoordinates(std::uint32_t tile) const { return {tile % split_, tile / split_}; }

glm::uvec2 ShadowAtlasLayout::tileOffset(std::uint32_t tile) const { return tileCoordinates(tile) * tileSize(); }

TileTexelBounds ShadowAtlasLayout::tileTexelBounds(std::uint32_t tile) const
{
    const glm::ivec2 first(tileOffset(tile));
    return {first, first + static_cast<int>(tileSize() - 1)};
}

rhi::Viewport ShadowAtlasLayout::viewport(std::uint32_t tile) const
{
    const glm::uvec2 offset = tileOffset(tile);
    const auto size = static_cast<float>(tileSize());
    return {static_cast<float>(offset.x), static_cast<float>(offset.y), size, size};
}

glm::mat4 ShadowAtlasLayout::tileToAtlas(std::uint32_t tile) const
{
    return shadows::tileToAtlas(tileOffset(tile), tileSize(), atlasSize_);
}

} // namespace penumbra::shadows
