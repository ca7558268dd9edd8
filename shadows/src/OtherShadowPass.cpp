#include "penumbra/shadows/OtherShadowPass.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::shadows {

OtherShadowPass::OtherShadowPass(rhi::Device& device, const CasterVertexFormat& vertexFormat)
    : draws_(device, vertexFormat)
{
}

std::uint32_t OtherShadowPass::record(rhi::CommandList& commands, const ShadowAtlas& atlas,
                                      const OtherShadowPlan& plan, std::span<const ShadowCaster> casters)
{
    if (atlas.size() != plan.atlas.atlasSize())
        throw rhi::Error(fmt::format("other shadow atlas is {} texels wide, the plan was made for {}", atlas.size(),
                                     plan.atlas.atlasSize()));
    draws_.reset();
    std::uint32_t draws = 0;
    commands.beginPass({.framebuffer = &atlas.framebuffer(), .clearColor = std::nullopt, .clearDepth = true});
    for (const OtherAtlasTile& tile : plan.tiles) {
        commands.setViewport(tile.viewport);
        commands.setScissor(scissorOf(tile.viewport));
        // The dither follows the tile's own texel grid: local lights do not move with the camera.
        const ShadowViewDraw view{.viewProjection = tile.view.viewProjection,
                                  .slopeScaleBias = tile.view.slopeScaleBias,
                                  .ditherOrigin = -glm::vec2(plan.atlas.tileOffset(tile.tile))};
        draws += draws_.draw(commands, atlas.format(), view, tile.view.casters, casters);
    }
    commands.endPass();
    return draws;
}

} // namespace penumbra::shadows
