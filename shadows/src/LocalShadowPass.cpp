#include "penumbra/shadows/LocalShadowPass.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::shadows {
namespace {

void checkCubeCount(const ShadowCubes& cubes, const LocalShadowPlan& plan)
{
    if (cubes.cubeCount() < plan.cubes.size())
        throw rhi::Error(fmt::format("{} shadow cube maps, the plan needs {}", cubes.cubeCount(), plan.cubes.size()));
}

} // namespace

LocalShadowPass::LocalShadowPass(rhi::Device& device, const CasterVertexFormat& vertexFormat)
    : draws_(device, vertexFormat)
{
}

std::vector<ShadowTileDraw> LocalShadowPass::tileDraws(const LocalShadowPlan& plan)
{
    std::vector<ShadowTileDraw> tiles;
    for (const LocalAtlasTile& tile : plan.tiles)
        // The dither follows the tile's own texel grid: local lights do not move with the camera.
        tiles.push_back({tile.tile,
                         tile.viewport,
                         {.viewProjection = tile.view.viewProjection,
                          .slopeScaleBias = tile.view.slopeScaleBias,
                          .depthBias = tile.view.depthBias,
                          .ditherOrigin = -glm::vec2(tile.viewport.x, tile.viewport.y),
                          .normalOffset = tile.view.normalOffset},
                         tile.view.casters,
                         tile.view.volume});
    return tiles;
}

std::uint32_t LocalShadowPass::record(rhi::CommandList& commands, const ShadowAtlas& atlas, const ShadowCubes& cubes,
                                      const LocalShadowPlan& plan, std::span<const ShadowCaster> casters,
                                      bool clearAtlas, const std::optional<CulledTiles>& culled)
{
    checkCubeCount(cubes, plan);
    if (!plan.tiles.empty() && atlas.size() != plan.atlasSize)
        throw rhi::Error(fmt::format("local shadow atlas is {} texels wide, the plan was made for {}", atlas.size(),
                                     plan.atlasSize));
    draws_.reset();
    std::uint32_t draws = 0;
    commands.beginPass({.framebuffer = &atlas.framebuffer(), .clearColor = std::nullopt, .clearDepth = clearAtlas});
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
    return draws + drawCubes(commands, cubes, plan, casters);
}

std::uint32_t LocalShadowPass::recordCubes(rhi::CommandList& commands, const ShadowCubes& cubes,
                                           const LocalShadowPlan& plan, std::span<const ShadowCaster> casters)
{
    checkCubeCount(cubes, plan);
    draws_.reset();
    return drawCubes(commands, cubes, plan, casters);
}

std::uint32_t LocalShadowPass::drawCubes(rhi::CommandList& commands, const ShadowCubes& cubes,
                                         const LocalShadowPlan& plan, std::span<const ShadowCaster> casters)
{
    std::uint32_t draws = 0;
    const auto size = static_cast<float>(cubes.faceSize());
    for (std::uint32_t cube = 0; cube < plan.cubes.size(); ++cube)
        for (const CubeFace face : rhi::allCubeFaces) {
            const LocalShadowView& faceView = plan.cubes[cube].faces[static_cast<std::size_t>(face)];
            commands.beginPass({.framebuffer = &cubes.framebuffer(rhi::cubeLayer(cube, face)),
                                .clearColor = std::nullopt,
                                .clearDepth = true});
            const rhi::Viewport viewport{0.0f, 0.0f, size, size};
            commands.setViewport(viewport);
            commands.setScissor(scissorOf(viewport));
            const ShadowViewDraw view{.viewProjection = faceView.viewProjection,
                                      .slopeScaleBias = faceView.slopeScaleBias,
                                      .depthBias = faceView.depthBias,
                                      .mirrored = true,
                                      .normalOffset = faceView.normalOffset};
            draws += draws_.draw(commands, cubes.format(), view, faceView.casters, casters);
            commands.endPass();
        }
    return draws;
}

} // namespace penumbra::shadows
