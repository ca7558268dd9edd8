#include "DepthFitPasses.hpp"

#include "DepthPrepass.hpp"
#include "DepthReduction.hpp"

#include "penumbra/render/FrameResources.hpp"

namespace penumbra::render {

std::string DepthReductionPass::name() const { return std::string(frame::kDepthReductionPass); }

bool DepthReductionPass::setup(FramePassBuilder& builder)
{
    if (!state_.depthFit)
        return false;
    builder.read(frame::kLitDepth);
    builder.write(frame::kDepthHistogram, ResourceUse::StorageWrite);
    return true;
}

void DepthReductionPass::execute(const FramePassContext& context)
{
    reduction_->record(context.commands(), context.texture(frame::kLitDepth), state_.litFrameUniforms,
                       state_.depthFitLights, state_.depthFitShadowFar);
}

} // namespace penumbra::render
