#pragma once

#include "ContentHash.hpp"

#include "penumbra/shadows/ShadowCaster.hpp"
#include "penumbra/shadows/ShadowCasterDraws.hpp"

#include <cstdint>
#include <span>

namespace penumbra::render {

// What a tile's depth is drawn from: its place (the viewport; not its index, which may change while the tile stays
// put), its view and biases.
inline void addTileView(ContentHash& h, const shadows::ShadowTileDraw& tile)
{
    const shadows::ShadowViewDraw& v = tile.view;
    h.add(tile.viewport).add(v.viewProjection).add(v.slopeScaleBias).add(v.depthBias).add(v.pancake);
    h.add(v.mirrored);
    h.add(v.ditherOrigin).add(v.normalOffset.reach).add(v.normalOffset.light);
}

// One caster as the GPU objects and values it is drawn with this frame.
inline void addCaster(ContentHash& h, const shadows::ShadowCaster& c)
{
    h.add(c.vertices).add(c.indices).add(c.indexCount).add(c.model).add(c.pose).add(c.mode).add(c.alpha);
    h.add(c.alphaCutoff).add(c.baseColorMap).add(c.textured).add(c.baseColorUv).add(c.doubleSided);
}

// ... and the casters drawn into it.
inline void addTileCasters(ContentHash& h, const shadows::ShadowTileDraw& tile,
                           std::span<const shadows::ShadowCaster> casters)
{
    for (const std::uint32_t i : tile.casters)
        addCaster(h.add(i), casters[i]);
}

// One tile's key in two parts, so that a cache can say which changed: its view (addTileView) and its casters
// (addTileCasters).
struct TileKey {
    std::uint64_t view = 0;
    std::uint64_t casters = 0;

    bool operator==(const TileKey&) const = default;
};

inline TileKey tileKey(const shadows::ShadowTileDraw& tile, std::span<const shadows::ShadowCaster> casters)
{
    ContentHash view, drawn;
    addTileView(view, tile);
    addTileCasters(drawn, tile, casters);
    return {view.value(), drawn.value()};
}

// The same key with each caster's addCaster hash computed once per frame and shared by every tile that draws it
// (casterHash(i) gives caster i's), for atlases of hundreds of tiles over the same casters. Its caster part is not
// tileKey's: keys of the two kinds must not be compared with each other.
template <typename CasterHash>
TileKey sharedCasterTileKey(const shadows::ShadowTileDraw& tile, const CasterHash& casterHash)
{
    ContentHash view, drawn;
    addTileView(view, tile);
    for (const std::uint32_t i : tile.casters)
        drawn.add(i).add(casterHash(i));
    return {view.value(), drawn.value()};
}

} // namespace penumbra::render
