#pragma once

#include "penumbra/rhi/Device.hpp"
#include "penumbra/shadows/ShadowAtlas.hpp"
#include "penumbra/shadows/ShadowCaster.hpp"
#include "penumbra/shadows/ShadowCasterDraws.hpp"
#include "penumbra/shadows/StaticShadowPlanner.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <span>

namespace penumbra::shadows {

// Renders static shadow maps into a static atlas, keeping the tiles of the maps it is not given: each map's tiles
// are cleared to the far plane one by one (a full-tile triangle that writes the far depth), then its casters drawn
// with the light's biases, as the realtime passes draw them.
class StaticShadowPass {
public:
    StaticShadowPass(rhi::Device& device, const CasterVertexFormat& vertexFormat);

    // Records the maps' tiles (all into `atlas`); returns the caster draws issued. `clearAll` clears the whole
    // atlas first (a new atlas, whose other tiles hold nothing yet). Submit `commands` before recording again.
    std::uint32_t record(rhi::CommandList& commands, const ShadowAtlas& atlas,
                         std::span<const StaticShadowMap* const> maps, std::span<const ShadowCaster> casters,
                         bool clearAll);

private:
    const rhi::Pipeline& clearPipeline(rhi::Format format);

    rhi::Device& device_;
    ShadowCasterDraws draws_;
    std::unique_ptr<rhi::Shader> clearVertex_;
    std::unique_ptr<rhi::Shader> clearFragment_;
    std::map<rhi::Format, std::unique_ptr<rhi::Pipeline>> clearPipelines_;
};

} // namespace penumbra::shadows
