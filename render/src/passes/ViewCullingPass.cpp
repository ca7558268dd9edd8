#include "ViewCullingPass.hpp"

#include "penumbra/render/FrameResources.hpp"

namespace penumbra::render {

std::string ViewCullingPass::name() const { return std::string(frame::kViewCullingPass); }

bool ViewCullingPass::setup(FramePassBuilder& builder)
{
    if (!state_.viewCulling)
        return false;
    builder.write(frame::kViewCulledInstances, ResourceUse::StorageWrite);
    builder.write(frame::kViewCulledDraws, ResourceUse::StorageWrite);
    return true;
}

void ViewCullingPass::execute(const FramePassContext& context) { state_.viewCulling->dispatch(context.commands()); }

} // namespace penumbra::render
