#pragma once

#include "penumbra/rhi/Device.hpp"
#include "penumbra/shadows/LocalShadowPlanner.hpp"
#include "penumbra/shadows/ShadowAtlas.hpp"
#include "penumbra/shadows/ShadowCaster.hpp"
#include "penumbra/shadows/ShadowCasterDraws.hpp"
#include "penumbra/shadows/ShadowCubes.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace penumbra::shadows {

// Renders the casters of a spot and point shadow plan: one pass over the local atlas, every tile in its
// viewport and scissor with its light's slope-scale bias, then (CubeMap mode) one pass per cube face
// layer, culling through the mirrored face views. Perspective views, so nothing is pancaked.
class LocalShadowPass {
public:
    // Builds the caster pipelines for vertices of `vertexFormat`.
    LocalShadowPass(rhi::Device& device, const CasterVertexFormat& vertexFormat);

    // Records the pass; returns the caster draws issued. The uniforms it writes stay valid until the
    // next record(), so submit `commands` before recording again.
    // `cubes` must hold at least plan.cubes.size() cubes; `atlas` may be any size where the plan has no tile.
    // `clearAtlas` false draws over what the atlas holds (cached static depth); cubes are always cleared.
    // With `culled`, the atlas tiles draw what the GPU culled for them (indirectly) instead of the plan's lists.
    std::uint32_t record(rhi::CommandList& commands, const ShadowAtlas& atlas, const ShadowCubes& cubes,
                         const LocalShadowPlan& plan, std::span<const ShadowCaster> casters, bool clearAtlas = true,
                         const std::optional<CulledTiles>& culled = std::nullopt);
    // Records the cube-map half of record() alone (each face cleared and drawn): for an atlas whose tiles are drawn
    // elsewhere (render's per-light tile cache). `cubes` must hold at least plan.cubes.size() cubes.
    std::uint32_t recordCubes(rhi::CommandList& commands, const ShadowCubes& cubes, const LocalShadowPlan& plan,
                              std::span<const ShadowCaster> casters);

    // Every atlas tile of the plan as the pass draws it (not the cube faces).
    static std::vector<ShadowTileDraw> tileDraws(const LocalShadowPlan& plan);

private:
    std::uint32_t drawCubes(rhi::CommandList& commands, const ShadowCubes& cubes, const LocalShadowPlan& plan,
                            std::span<const ShadowCaster> casters);

    ShadowCasterDraws draws_;
};

} // namespace penumbra::shadows
