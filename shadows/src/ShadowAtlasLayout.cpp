#include "penumbra/shadows/ShadowAtlasLayout.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::shadows {

ShadowAtlasLayout::ShadowAtlasLayout(std::uint32_t atlasSize, std::uint32_t tileCount)
    : atlasSize_(atlasSize), tileCount_(tileCount), split_(tileCount <= 1    ? 1
                                                           : tileCount <= 4  ? 2
                                                           : tileCount <= 16 ? 4
                                                                             : 8)
{
    if (tileCount > maxAtlasTiles)
        throw rhi::Error(fmt::format("shadow atlas: {} tiles, allowed 0..{}", tileCount, maxAtlasTiles));
    if (atlasSize == 0 || atlasSize % split_ != 0)
        throw rhi::Error(
            fmt::format("shadow atlas: size {} cannot be split into {} x {} tiles", atlasSize, split_, split_));
}

glm::uvec2 ShadowAtlasLayout::tileCoordinates(std::uint32_t tile) const { return {tile % split_, tile / split_}; }

glm::uvec2 ShadowAtlasLayout::tileOffset(std::uint32_t tile) const { return tileCoordinates(tile) * tileSize(); }

glm::vec4 ShadowAtlasLayout::tileTexelBounds(std::uint32_t tile) const
{
    const glm::vec2 first(tileOffset(tile));
    return {first, first + static_cast<float>(tileSize() - 1)};
}

rhi::Viewport ShadowAtlasLayout::viewport(std::uint32_t tile) const
{
    const glm::uvec2 offset = tileOffset(tile);
    const auto size = static_cast<float>(tileSize());
    return {static_cast<float>(offset.x), static_cast<float>(offset.y), size, size};
}

glm::mat4 ShadowAtlasLayout::tileToAtlas(std::uint32_t tile) const
{
    // atlas uv = (tile coordinates + tile uv) / split.
    const float scale = 1.0f / static_cast<float>(split_);
    const glm::uvec2 coordinates = tileCoordinates(tile);
    glm::mat4 m(1.0f);
    m[0][0] = scale;
    m[1][1] = scale;
    m[3][0] = static_cast<float>(coordinates.x) * scale;
    m[3][1] = static_cast<float>(coordinates.y) * scale;
    return m;
}

} // namespace penumbra::shadows
