#include "penumbra/shadows/DirectionalShadowPass.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::shadows {

glm::vec2 ditherOrigin(const DirectionalShadowCascade& cascade, const ShadowAtlasLayout& atlas, std::uint32_t tile)
{
    const glm::vec2 centre = glm::round(cascade.snappedCentre / cascade.texelSize);
    const glm::vec2 offset = glm::vec2(atlas.tileOffset(tile)) + 0.5f * static_cast<float>(atlas.tileSize());
    return {centre.x - offset.x, -centre.y - offset.y};
}

DirectionalShadowPass::DirectionalShadowPass(rhi::Device& device, const CasterVertexFormat& vertexFormat)
    : draws_(device, vertexFormat)
{
}

std::vector<ShadowTileDraw> DirectionalShadowPass::tileDraws(const DirectionalShadowPlan& plan)
{
    std::vector<ShadowTileDraw> tiles;
    for (const ShadowedDirectionalLight& light : plan.lights)
        for (std::uint32_t c = 0; c < light.cascades.size(); ++c) {
            const DirectionalCascadePlan& cascade = light.cascades[c];
            tiles.push_back({cascade.tile,
                             cascade.viewport,
                             {.viewProjection = cascade.fit.viewProjection,
                              .slopeScaleBias = light.slopeScaleBias,
                              .depthBias = light.depthBias,
                              .pancake = true,
                              .ditherOrigin = ditherOrigin(cascade.fit, plan.atlas, cascade.tile),
                              .normalOffset = casterNormalOffset(plan, light, c)},
                             cascade.casters.casters,
                             cascade.volume});
        }
    return tiles;
}

std::uint32_t DirectionalShadowPass::record(rhi::CommandList& commands, const ShadowAtlas& atlas,
                                            const DirectionalShadowPlan& plan, std::span<const ShadowCaster> casters,
                                            bool clear, const std::optional<CulledTiles>& culled)
{
    if (!plan.lights.empty() && atlas.size() != plan.atlas.atlasSize())
        throw rhi::Error(fmt::format("shadow atlas is {} texels wide, the plan was made for {}", atlas.size(),
                                     plan.atlas.atlasSize()));
    draws_.reset();
    std::uint32_t draws = 0;
    commands.beginPass({.framebuffer = &atlas.framebuffer(), .clearColor = std::nullopt, .clearDepth = clear});
    const std::vector<ShadowTileDraw> tiles = tileDraws(plan);
    for (std::uint32_t i = 0; i < tiles.size(); ++i) {
        const ShadowTileDraw& tile = tiles[i];
        commands.setViewport(tile.viewport);
        commands.setScissor(scissorOf(tile.viewport));
        draws += culled ? draws_.drawCulled(commands, atlas.format(), tile.view, culled->culling, culled->firstTile + i,
                                            casters)
                        : draws_.draw(commands, atlas.format(), tile.view, tile.casters, casters);
    }
    commands.endPass();
    return draws;
}

} // namespace penumbra::shadows
