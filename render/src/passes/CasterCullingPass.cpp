#include "CasterCullingPass.hpp"

#include "penumbra/render/FrameResources.hpp"
#include "penumbra/shadows/DirectionalShadowPass.hpp"
#include "penumbra/shadows/LocalShadowPass.hpp"

namespace penumbra::render {

void prepareCasterCulling(shadows::GpuCasterCulling& culling, std::span<const shadows::ShadowCaster> casters,
                          const GpuScene& scene, const shadows::DirectionalShadowPlan& plan,
                          const shadows::LocalShadowPlan& localPlan)
{
    std::vector<shadows::CasterVolume> volumes;
    bool normalMatrices = false;
    for (const std::vector<shadows::ShadowTileDraw>& tiles :
         {shadows::DirectionalShadowPass::tileDraws(plan), shadows::LocalShadowPass::tileDraws(localPlan)})
        for (const shadows::ShadowTileDraw& tile : tiles) {
            volumes.push_back(tile.volume);
            normalMatrices |= tile.view.normalOffset.reach > 0.0f;
        }
    culling.prepare(casters, scene.casterBounds(), volumes, normalMatrices, &scene.casterChanges());
}

std::string CasterCullingPass::name() const { return std::string(frame::kCasterCullingPass); }

bool CasterCullingPass::setup(FramePassBuilder& builder)
{
    if (!state_.culling)
        return false;
    builder.write(frame::kCulledInstances, ResourceUse::StorageWrite);
    builder.write(frame::kCulledDraws, ResourceUse::StorageWrite);
    return true;
}

void CasterCullingPass::execute(const FramePassContext& context) { state_.culling->dispatch(context.commands()); }

} // namespace penumbra::render
