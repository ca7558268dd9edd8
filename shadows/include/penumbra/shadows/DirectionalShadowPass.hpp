#pragma once

#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/UniformArena.hpp"
#include "penumbra/shadows/DirectionalShadowPlanner.hpp"
#include "penumbra/shadows/ShadowAtlas.hpp"
#include "penumbra/shadows/ShadowCaster.hpp"
#include "penumbra/shadows/ShadowCasterDraws.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace penumbra::shadows {

// Added to gl_FragCoord in the tile, gives the texel's index in the light-space grid that the stable
// fit snaps to: the same for the same world texel whatever the camera does (x right, y down the tile).
glm::vec2 ditherOrigin(const DirectionalShadowCascade& cascade, const ShadowAtlasLayout& atlas, std::uint32_t tile);

// Renders the casters of a directional shadow plan into an atlas: one pass, every tile in its
// viewport and scissor, each light's slope-scale bias, casters in front of the near plane pancaked
// (depth clamp where the device has it, else the shader clamp onto the convention's near value).
class DirectionalShadowPass {
public:
    // Builds the caster pipelines for vertices of `vertexFormat`.
    DirectionalShadowPass(rhi::Device& device, const CasterVertexFormat& vertexFormat);

    // Records the pass; returns the caster draws issued. The uniforms it writes stay valid until the
    // next record(), so submit `commands` before recording again. `atlas` may be any size where the plan has no
    // shadowed light. `clear` false draws over what the atlas holds (cached static depth). With `culled`, the tiles
    // draw what the GPU culled for them (indirectly) instead of the plan's lists.
    std::uint32_t record(rhi::CommandList& commands, const ShadowAtlas& atlas, const DirectionalShadowPlan& plan,
                         std::span<const ShadowCaster> casters, bool clear = true,
                         const std::optional<CulledTiles>& culled = std::nullopt);

    // Every cascade tile of the plan as the pass draws it: viewport, view, biases, casters.
    static std::vector<ShadowTileDraw> tileDraws(const DirectionalShadowPlan& plan);

private:
    ShadowCasterDraws draws_;
};

} // namespace penumbra::shadows
