#include "CullingPasses.hpp"

#include "penumbra/render/FrameResources.hpp"
#include "penumbra/shadows/DirectionalShadowPass.hpp"
#include "penumbra/shadows/LocalShadowPass.hpp"

namespace penumbra::render {

void prepareCasterCulling(shadows::GpuCasterCulling& culling, std::span<const shadows::ShadowCaster> casters,
                          const GpuScene& scene, const shadows::DirectionalShadowPlan& plan,
                          const shadows::LocalShadowPlan& localPlan)
{
    std::vector<shadows::CasterVolume> volumes;
    for (const std::vector<shadows::ShadowTileDraw>& tiles :
         {shadows::DirectionalShadowPass::tileDraws(plan), shadows::LocalShadowPass::tileDraws(localPlan)})
        for (const shadows::ShadowTileDraw& tile : tiles)
            volumes.push_back(tile.volume);
    culling.prepare(casters, scene.casterBounds(), volumes, &scene.casterChanges());
}

shadows::GpuCasterCulling* CullingPass::culling() const
{
    return kind_ == Kind::Casters ? state_.culling : state_.viewCulling;
}

std::string CullingPass::name() const
{
    return std::string(kind_ == Kind::Casters ? frame::kCasterCullingPass : frame::kViewCullingPass);
}

bool CullingPass::setup(FramePassBuilder& builder)
{
    if (!culling())
        return false;
    const CulledBuffers& written = kind_ == Kind::Casters ? kCulledCasters : kViewCulled;
    builder.write(written.instances, ResourceUse::StorageWrite);
    builder.write(written.draws, ResourceUse::StorageWrite);
    return true;
}

void CullingPass::execute(const FramePassContext& context) { culling()->dispatch(context.commands()); }

} // namespace penumbra::render
