#include "penumbra/shadows/AtlasMatrix.hpp"

namespace penumbra::shadows {

glm::mat4 worldToAtlas(const glm::mat4& viewProjection, std::uint32_t tile, const ShadowAtlasLayout& layout,
                       const rhi::Conventions& conventions)
{
    // No reversed-Z negation as in the document: clipToTexture yields the window depth the atlas
    // holds, reversed or not, and the lookup compares with conventions.shadowCompareOp().
    return layout.tileToAtlas(tile) * conventions.clipToTexture() * viewProjection;
}

glm::mat4 worldToAtlas(const glm::mat4& viewProjection, glm::uvec2 offset, std::uint32_t tileSize,
                       std::uint32_t atlasSize, const rhi::Conventions& conventions)
{
    return tileToAtlas(offset, tileSize, atlasSize) * conventions.clipToTexture() * viewProjection;
}

glm::mat4 tileToAtlas(glm::uvec2 offset, std::uint32_t tileSize, std::uint32_t atlasSize)
{
    // atlas uv = (tile offset + tile uv x tile size) / atlas size.
    const auto atlas = static_cast<float>(atlasSize);
    glm::mat4 m(1.0f);
    m[0][0] = static_cast<float>(tileSize) / atlas;
    m[1][1] = m[0][0];
    m[3][0] = static_cast<float>(offset.x) / atlas;
    m[3][1] = static_cast<float>(offset.y) / atlas;
    return m;
}

} // namespace penumbra::shadows
