#pragma once

#include "../static/TileKeys.hpp"

#include "penumbra/rhi/Device.hpp"
#include "penumbra/shadows/LocalShadowPlanner.hpp"
#include "penumbra/shadows/ShadowAtlas.hpp"
#include "penumbra/shadows/ShadowCaster.hpp"
#include "penumbra/shadows/StaticShadowPass.hpp"

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <tuple>
#include <vector>

namespace penumbra::render {

// A spot or point light whose atlas tiles a frame drew again, and why.
struct LocalShadowRedraw {
    shadows::LightKind kind = shadows::LightKind::Spot;
    std::uint32_t lightIndex = 0;
    std::string reason;
};

// What LocalTileCache::record drew.
struct LocalTileDraws {
    std::uint32_t casterDraws = 0;
    std::uint32_t tilesDrawn = 0; // atlas tiles drawn this frame
    std::uint32_t tilesCached = 0; // atlas tiles kept from an earlier frame
    std::vector<LocalShadowRedraw> redraws; // per light with a tile drawn, in tile order
};

// Per-light caching of the realtime local atlas: a tile is drawn again only when its light's view (place, matrices,
// biases) or a caster in it changed since the frame that last drew it, and every other tile keeps its depth. Tiles
// are found by their place in the atlas, so a light that keeps its place (ShadowAtlasPacker's hysteresis) keeps its
// depth while other lights come and go. Godot
// redraws a positional light's shadow only when the light or a caster in its range moved ("Shadow atlas", Godot docs,
// "Lights and shadows"); HDRP's cached shadows are the same idea. A changed tile is cleared on its own and drawn as
// the realtime pass draws it, so the atlas holds the depth of drawing every tile, bit for bit.
class LocalTileCache {
public:
    LocalTileCache(rhi::Device& device, const shadows::CasterVertexFormat& vertexFormat);

    // Records the atlas tiles of `plan` that changed into `atlas`; the others keep what an earlier record() drew
    // into this atlas. The first record() after invalidate() clears the whole atlas and draws every tile.
    LocalTileDraws record(rhi::CommandList& commands, const shadows::ShadowAtlas& atlas,
                          const shadows::LocalShadowPlan& plan, std::span<const shadows::ShadowCaster> casters);
    // Forgets every tile: the atlas was made anew or drawn by another pass.
    void invalidate()
    {
        keys_.clear();
        valid_ = false;
    }

private:
    shadows::StaticShadowPass pass_;
    // A tile's place in the atlas: its top-left texel and size. Tiles of one frame never overlap, so a place that
    // holds the same key as last frame holds the depth drawn then, whatever the tile's index.
    using TilePlace = std::tuple<float, float, float>;
    std::map<TilePlace, TileKey> keys_; // per atlas tile of the last record(), as drawn
    std::vector<std::uint64_t> casterHashes_; // record()'s per caster, kept to spare the allocation
    bool valid_ = false;
};

} // namespace penumbra::render
