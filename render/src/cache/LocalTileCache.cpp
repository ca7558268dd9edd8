#include "LocalTileCache.hpp"

#include "../static/TileKeys.hpp"

#include "penumbra/shadows/LocalShadowPass.hpp"

#include <optional>

namespace penumbra::render {
namespace {

// The light each tile of the plan belongs to: a spot light's tile, a point light's six (Atlas mode).
std::map<std::uint32_t, LocalShadowRedraw> tileLights(const shadows::LocalShadowPlan& plan)
{
    std::map<std::uint32_t, LocalShadowRedraw> lights;
    for (std::uint32_t i = 0; i < plan.spotTiles.size(); ++i)
        if (plan.spotTiles[i] >= 0)
            lights[static_cast<std::uint32_t>(plan.spotTiles[i])] = {shadows::LightKind::Spot, i, {}};
    if (plan.cubes.empty())
        for (std::uint32_t i = 0; i < plan.pointShadows.size(); ++i)
            for (std::uint32_t face = 0; plan.pointShadows[i] >= 0 && face < shadows::cubeFaceCount; ++face)
                lights[static_cast<std::uint32_t>(plan.pointShadows[i]) + face] = {shadows::LightKind::Point, i, {}};
    return lights;
}

} // namespace

LocalTileCache::LocalTileCache(rhi::Device& device, const shadows::CasterVertexFormat& vertexFormat)
    : pass_(device, vertexFormat)
{
}

LocalTileDraws LocalTileCache::record(rhi::CommandList& commands, const shadows::ShadowAtlas& atlas,
                                      const shadows::LocalShadowPlan& plan,
                                      std::span<const shadows::ShadowCaster> casters)
{
    const std::vector<shadows::ShadowTileDraw> tiles = shadows::LocalShadowPass::tileDraws(plan);
    const std::map<std::uint32_t, LocalShadowRedraw> lights = tileLights(plan);
    std::map<TilePlace, TileKey> keys;
    std::vector<const shadows::ShadowTileDraw*> changed;
    LocalTileDraws result;
    std::optional<LocalShadowRedraw> lastRedraw;
    // Each caster's hash is computed the first time a tile draws it (0: not yet). Without tiles nothing is hashed,
    // and clearing one slot per caster would be the frame's largest CPU cost at 10^6 casters (0.5 ms).
    casterHashes_.assign(tiles.empty() ? 0 : casters.size(), 0);
    const auto casterHash = [&](std::uint32_t i) {
        if (casterHashes_[i] == 0) {
            ContentHash h;
            addCaster(h, casters[i]);
            casterHashes_[i] = h.value() | 1u;
        }
        return casterHashes_[i];
    };
    for (const shadows::ShadowTileDraw& tile : tiles) {
        const TileKey key = sharedCasterTileKey(tile, casterHash);
        const TilePlace place{tile.viewport.x, tile.viewport.y, tile.viewport.width};
        keys[place] = key;
        const auto old = keys_.find(place);
        const char* reason = !valid_ || old == keys_.end()        ? "its tile is new"
                             : old->second.view != key.view       ? "its view changed"
                             : old->second.casters != key.casters ? "a caster in its view changed"
                                                                  : nullptr;
        if (!reason) {
            ++result.tilesCached;
            continue;
        }
        changed.push_back(&tile);
        // A point light's six tiles report once, for the first that changed.
        LocalShadowRedraw light = lights.at(tile.tile);
        if (lastRedraw && lastRedraw->kind == light.kind && lastRedraw->lightIndex == light.lightIndex)
            continue;
        light.reason = reason;
        lastRedraw = light;
        result.redraws.push_back(std::move(light));
    }
    result.tilesDrawn = static_cast<std::uint32_t>(changed.size());
    if (!changed.empty() || !valid_) {
        pass_.begin();
        result.casterDraws = pass_.record(commands, atlas, changed, casters, !valid_);
    }
    keys_ = std::move(keys);
    valid_ = true;
    return result;
}

} // namespace penumbra::render
