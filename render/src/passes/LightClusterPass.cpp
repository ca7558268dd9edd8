#include "LightClusterPass.hpp"

#include "../LocalLightTextures.hpp"

#include "penumbra/render/FrameResources.hpp"

namespace penumbra::render {

std::string LightClusterPass::name() const { return std::string(frame::kLightClusterPass); }

bool LightClusterPass::setup(FramePassBuilder& builder)
{
    if (!state_.gpuClusters)
        return false;
    builder.write(frame::kLightClusters, ResourceUse::StorageWrite);
    builder.write(frame::kLightIndices, ResourceUse::StorageWrite);
    return true;
}

void LightClusterPass::execute(const FramePassContext& context)
{
    state_.gpuClusters->recordGpuLists(context.commands(), context.texture(frame::kLightClusters),
                                       context.texture(frame::kLightIndices));
}

} // namespace penumbra::render
