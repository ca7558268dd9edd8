#pragma once

#include "TileKeys.hpp"

#include "penumbra/rhi/Device.hpp"
#include "penumbra/shadows/ShadowAtlas.hpp"
#include "penumbra/shadows/ShadowCaster.hpp"
#include "penumbra/shadows/ShadowCasterDraws.hpp"
#include "penumbra/shadows/StaticShadowPass.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace penumbra::render {

// RealtimeCasters::Dynamic: the static casters' depth of each tile of a realtime atlas, kept in a twin texture while
// the tile's view and its static casters stay as they were. A frame draws the tiles that changed into the twin,
// copies it into the atlas, and the realtime pass then draws the dynamic casters over it: the depth test keeps the
// nearest of both, the depth of drawing every caster, bit for bit (Unreal Engine's "Shadow Map Caching" of static
// primitives for movable lights works so).
class StaticTileCache {
public:
    StaticTileCache(rhi::Device& device, const shadows::CasterVertexFormat& vertexFormat, std::string name);

    // `tiles` with their static casters alone; returns the caster draws into the twin. Fills `atlas` with the
    // tiles' static depth (recorded: a copy in `commands`).
    std::uint32_t update(rhi::CommandList& commands, shadows::ShadowAtlas& atlas,
                         const std::vector<shadows::ShadowTileDraw>& tiles,
                         std::span<const shadows::ShadowCaster> casters);

private:
    rhi::Device& device_;
    std::string name_;
    shadows::StaticShadowPass pass_;
    std::unique_ptr<shadows::ShadowAtlas> twin_;
    std::map<std::uint32_t, TileKey> keys_; // per tile, as drawn into the twin
};

} // namespace penumbra::render
