#include "ShadowMapPasses.hpp"

#include "../FrameNotes.hpp"
#include "../cache/LocalTileCache.hpp"
#include "../static/StaticShadowCache.hpp"
#include "../static/StaticTileCache.hpp"

#include "penumbra/render/FrameResources.hpp"

namespace penumbra::render {

std::string StaticMapsPass::name() const { return std::string(frame::kStaticMapsPass); }

bool StaticMapsPass::setup(FramePassBuilder& builder)
{
    if (!cache_.drawsPending())
        return false;
    // The cache clears a static atlas made anew and draws the chosen tiles over the rest: both atlases are read too.
    builder.write(frame::kStaticDirectionalAtlas, ResourceUse::DrawOver);
    builder.write(frame::kStaticLocalAtlas, ResourceUse::DrawOver);
    readPosedVertices(builder, state_);
    return true;
}

void StaticMapsPass::execute(const FramePassContext& context)
{
    state_.stats->staticCasterDraws += cache_.record(context.commands(), state_.casters);
}

std::string StaticTilesPass::name() const
{
    return std::string(atlas_ == Atlas::Directional ? frame::kDirectionalStaticTilesPass
                                                    : frame::kLocalStaticTilesPass);
}

const std::vector<shadows::ShadowTileDraw>& StaticTilesPass::tiles() const
{
    return atlas_ == Atlas::Directional ? state_.staticTiles.directional : state_.staticTiles.local;
}

bool StaticTilesPass::setup(FramePassBuilder& builder)
{
    if (tiles().empty())
        return false;
    builder.write(atlas_ == Atlas::Directional ? frame::kDirectionalAtlas : frame::kLocalAtlas,
                  ResourceUse::TransferDestination);
    readPosedVertices(builder, state_);
    return true;
}

void StaticTilesPass::execute(const FramePassContext& context)
{
    shadows::ShadowAtlas& atlas =
        atlas_ == Atlas::Directional ? *state_.shadowMaps.directional : *state_.shadowMaps.local;
    state_.stats->staticCasterDraws += cache_.update(context.commands(), atlas, tiles(), state_.casters);
}

std::string DirectionalAtlasPass::name() const { return std::string(frame::kDirectionalAtlasPass); }

bool DirectionalAtlasPass::setup(FramePassBuilder& builder)
{
    builder.write(frame::kDirectionalAtlas,
                  state_.staticTiles.directional.empty() ? ResourceUse::RenderTarget : ResourceUse::DrawOver);
    readPosedVertices(builder, state_);
    readCulledCasters(builder, state_);
    return true;
}

void DirectionalAtlasPass::execute(const FramePassContext& context)
{
    const auto culled = state_.culling ? std::optional(shadows::CulledTiles{*state_.culling, 0}) : std::nullopt;
    state_.stats->casterDraws = pass_.record(context.commands(), *state_.shadowMaps.directional, plan_, state_.casters,
                                             state_.staticTiles.directional.empty(), culled);
}

std::string LocalAtlasPass::name() const { return std::string(frame::kLocalAtlasPass); }

bool LocalAtlasPass::setup(FramePassBuilder& builder)
{
    // Tiles kept from earlier frames, or the static casters' depth that StaticTilesPass copied in: drawn over.
    builder.write(frame::kLocalAtlas, ResourceUse::DrawOver);
    builder.write(frame::kShadowCubes);
    readPosedVertices(builder, state_);
    readCulledCasters(builder, state_);
    return true;
}

void LocalAtlasPass::execute(const FramePassContext& context)
{
    FrameStats& stats = *state_.stats;
    const std::uint32_t tiles = static_cast<std::uint32_t>(plan_.tiles.size());
    // Without tiles there are no GPU lists to draw: the cache below clears the atlas once, as on the CPU path, where
    // a pass drawing none would clear it every frame.
    if (state_.culling && tiles > 0) {
        // The GPU's lists are not the cache's keys: every tile is drawn anew, as the cache's first frame draws it.
        cache_.invalidate();
        stats.localCasterDraws =
            pass_.record(context.commands(), *state_.shadowMaps.local, *state_.shadowMaps.cubes, plan_, state_.casters,
                         true, shadows::CulledTiles{*state_.culling, state_.culledLocalTile});
        stats.localTilesDrawn = tiles;
        return;
    }
    if (!state_.staticTiles.local.empty()) {
        // Every tile starts from its static casters' depth this frame: nothing of the last frame's atlas is kept.
        cache_.invalidate();
        stats.localCasterDraws = pass_.record(context.commands(), *state_.shadowMaps.local, *state_.shadowMaps.cubes,
                                              plan_, state_.casters, false);
        stats.localTilesDrawn = tiles;
        return;
    }
    const LocalTileDraws drawn = cache_.record(context.commands(), *state_.shadowMaps.local, plan_, state_.casters);
    stats.localCasterDraws =
        drawn.casterDraws + pass_.recordCubes(context.commands(), *state_.shadowMaps.cubes, plan_, state_.casters);
    stats.localTilesDrawn = drawn.tilesDrawn;
    stats.localTilesCached = drawn.tilesCached;
    for (const LocalShadowRedraw& redraw : drawn.redraws)
        stats.localShadowUpdates.push_back(localShadowUpdate(scene_, redraw.kind, redraw.lightIndex, redraw.reason));
}

} // namespace penumbra::render
