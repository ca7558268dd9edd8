#include "penumbra/shadows/AtlasMatrix.hpp"

namespace penumbra::shadows {

glm::mat4 worldToAtlas(const glm::mat4& viewProjection, std::uint32_t tile, const ShadowAtlasLayout& layout,
                       const rhi::Conventions& conventions)
{
    // No reversed-Z negation as in the document: clipToTexture yields the window depth the atlas
    // holds, reversed or not, and the lookup compares with conventions.shadowCompareOp().
    return layout.tileToAtlas(tile) * conventions.clipToTexture() * viewProjection;
}

} // namespace penumbra::shadows
