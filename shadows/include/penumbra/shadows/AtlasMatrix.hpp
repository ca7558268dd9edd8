#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/shadows/ShadowAtlasLayout.hpp"

#include <cstdint>
#include <glm/mat4x4.hpp>

namespace penumbra::shadows {

// World point -> (u, v, depth, 1) in the atlas: u, v over the whole atlas with v = 0 on the top
// row, depth the window depth the shadow pass stored for it. ConvertToAtlasMatrix of Catlike
// Coding's "Directional Shadows" tutorial (section "Sampling Shadows") for every convention: tileToAtlas *
// clipToTexture * viewProjection.
glm::mat4 worldToAtlas(const glm::mat4& viewProjection, std::uint32_t tile, const ShadowAtlasLayout& layout,
                       const rhi::Conventions& conventions);

} // namespace penumbra::shadows
