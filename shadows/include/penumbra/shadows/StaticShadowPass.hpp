#pragma once

#include "penumbra/rhi/Device.hpp"
#include "penumbra/shadows/ShadowAtlas.hpp"
#include "penumbra/shadows/ShadowCaster.hpp"
#include "penumbra/shadows/ShadowCasterDraws.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <span>

namespace penumbra::shadows {

// Renders tiles into an atlas, keeping the tiles it is not given: each tile is cleared to the far plane on its own
// (a full-tile triangle that writes the far depth), then its casters drawn with the view's biases, as the realtime
// passes draw them. Static shadow maps and the cached static depth of realtime tiles are drawn so.
class StaticShadowPass {
public:
    // Builds the caster pipelines for vertices of `vertexFormat`.
    StaticShadowPass(rhi::Device& device, const CasterVertexFormat& vertexFormat);

    // Starts a command list's recordings: the caster uniforms of the last submitted one may be reused.
    void begin() { draws_.reset(); }
    // Records the tiles into `atlas`; returns the caster draws issued. `clearAll` clears the whole atlas first (a
    // new atlas, whose other tiles hold nothing yet). Several records may share a command list (the directional
    // and the local static atlas): their caster uniforms stay apart until the next begin(), which must follow the
    // submission.
    std::uint32_t record(rhi::CommandList& commands, const ShadowAtlas& atlas,
                         std::span<const ShadowTileDraw* const> tiles, std::span<const ShadowCaster> casters,
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
