#include "CasterCullingPass.hpp"

#include "penumbra/render/FrameResources.hpp"
#include "penumbra/shadows/DirectionalShadowPass.hpp"
#include "penumbra/shadows/LocalShadowPass.hpp"

namespace penumbra::render {

std::string CasterCullingPass::name() const { return std::string(frame::kCasterCullingPass); }

bool CasterCullingPass::setup(FramePassBuilder& builder)
{
    if (!state_.culling)
        return false;
    // Its results are buffers the atlas passes draw from, which the graph does not track: never culled.
    builder.keep();
    return true;
}

void CasterCullingPass::execute(const FramePassContext& context)
{
    std::vector<shadows::CasterVolume> volumes;
    bool normalMatrices = false;
    for (const std::vector<shadows::ShadowTileDraw>& tiles :
         {shadows::DirectionalShadowPass::tileDraws(plan_), shadows::LocalShadowPass::tileDraws(localPlan_)})
        for (const shadows::ShadowTileDraw& tile : tiles) {
            volumes.push_back(tile.volume);
            normalMatrices |= tile.view.normalOffset.reach > 0.0f;
        }
    state_.culling->record(context.commands(), state_.casters, scene_.casterBounds(), volumes, normalMatrices,
                           &scene_.casterChanges());
}

} // namespace penumbra::render
