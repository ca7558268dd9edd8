#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/shadows/ShadowAtlasLayout.hpp"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

namespace penumbra::shadows {

// World point -> (u, v, depth, 1) in the atlas: u, v over the whole atlas with v = 0 on the top
// row, depth the window depth the shadow pass stored for it. ConvertToAtlasMatrix of Catlike
// Coding's "Directional Shadows" tutorial (section "Sampling Shadows") for every convention: tileToAtlas *
// clipToTexture * viewProjection.
glm::mat4 worldToAtlas(const glm::mat4& viewProjection, std::uint32_t tile, const ShadowAtlasLayout& layout,
                       const rhi::Conventions& conventions);
// The same for a square tile of `tileSize` texels whose top-left texel is `offset` in an atlas of `atlasSize`.
glm::mat4 worldToAtlas(const glm::mat4& viewProjection, glm::uvec2 offset, std::uint32_t tileSize,
                       std::uint32_t atlasSize, const rhi::Conventions& conventions);

// Maps such a tile's texture coordinates (u, v in [0, 1], depth) to the atlas's; depth passes through.
glm::mat4 tileToAtlas(glm::uvec2 offset, std::uint32_t tileSize, std::uint32_t atlasSize);

} // namespace penumbra::shadows
