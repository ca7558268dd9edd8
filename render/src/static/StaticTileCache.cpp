#include "StaticTileCache.hpp"

namespace penumbra::render {

StaticTileCache::StaticTileCache(rhi::Device& device, const shadows::CasterVertexFormat& vertexFormat, std::string name)
    : device_(device), name_(std::move(name)), pass_(device, vertexFormat)
{
}

std::uint32_t StaticTileCache::update(rhi::CommandList& commands, shadows::ShadowAtlas& atlas,
                                      const std::vector<shadows::ShadowTileDraw>& tiles,
                                      std::span<const shadows::ShadowCaster> casters)
{
    const bool fresh = !twin_ || twin_->size() != atlas.size() || twin_->format() != atlas.format();
    if (fresh) {
        twin_ = std::make_unique<shadows::ShadowAtlas>(device_, atlas.size(), atlas.format(), name_);
        keys_.clear();
    }
    std::map<std::uint32_t, TileKey> keys;
    std::vector<const shadows::ShadowTileDraw*> changed;
    for (const shadows::ShadowTileDraw& tile : tiles) {
        const TileKey key = tileKey(tile, casters);
        keys[tile.tile] = key;
        const auto old = keys_.find(tile.tile);
        if (fresh || old == keys_.end() || old->second != key)
            changed.push_back(&tile);
    }
    keys_ = std::move(keys);
    std::uint32_t draws = 0;
    if (!changed.empty() || fresh) {
        pass_.begin();
        draws = pass_.record(commands, *twin_, changed, casters, fresh);
    }
    commands.copyTexture(twin_->texture(), 0, atlas.texture(), 0);
    return draws;
}

} // namespace penumbra::render
