#include "PrepassPasses.hpp"

#include "ContactShadowPass.hpp"
#include "DepthPrepass.hpp"
#include "ScreenSpaceShadowPass.hpp"

#include "penumbra/render/FrameResources.hpp"

namespace penumbra::render {

std::string DepthPrepassPass::name() const { return std::string(frame::kDepthPrepass); }

bool DepthPrepassPass::setup(FramePassBuilder& builder)
{
    // Single-sampled, the screen-space path's receiver prepass is the depth prepass.
    if (!state_.desc->depthPrepass || (state_.screenSpace && !state_.multisampled))
        return false;
    builder.write(state_.multisampled ? frame::kMultisampledDepth : frame::kLitDepth);
    if (writesViewDepth())
        builder.write(frame::kContactViewDepth);
    readLitDraws(builder, state_);
    return true;
}

void DepthPrepassPass::execute(const FramePassContext& context)
{
    if (writesViewDepth()) {
        state_.stats->depthPrepassDraws +=
            state_.contactShadows->prepass(false).record(context.commands(),
                                                         context.framebuffer({frame::kContactViewDepth},
                                                                             frame::kLitDepth),
                                                         scene_, state_.litDraws, state_.litFrame);
        return;
    }
    const rhi::Framebuffer& target =
        context.framebuffer({}, state_.multisampled ? frame::kMultisampledDepth : frame::kLitDepth);
    state_.stats->depthPrepassDraws +=
        prepass_.record(context.commands(), target, scene_, state_.litDraws, state_.litFrame);
}

std::string SingleSampledDepthPass::name() const { return std::string(frame::kSingleSampledDepthPrepass); }

bool SingleSampledDepthPass::setup(FramePassBuilder& builder)
{
    if (!(state_.depthFit || state_.contact) || !state_.multisampled || state_.screenSpace)
        return false;
    builder.write(frame::kLitDepth);
    if (state_.contact)
        builder.write(frame::kContactViewDepth);
    readLitDraws(builder, state_);
    return true;
}

void SingleSampledDepthPass::execute(const FramePassContext& context)
{
    // With contact shadows, their prepass, which writes the view depth too.
    const DepthPrepass& prepass = state_.contact ? state_.contactShadows->prepass(false) : *prepass_;
    const rhi::Framebuffer& target = state_.contact ? context.framebuffer({frame::kContactViewDepth}, frame::kLitDepth)
                                                    : context.framebuffer({}, frame::kLitDepth);
    state_.stats->depthPrepassDraws +=
        prepass.record(context.commands(), target, scene_, state_.litDraws, state_.litFrame);
}

std::string ReceiverPrepassPass::name() const { return std::string(frame::kReceiverPrepass); }

bool ReceiverPrepassPass::setup(FramePassBuilder& builder)
{
    if (!state_.screenSpace)
        return false;
    builder.write(frame::kLitDepth);
    builder.write(frame::kReceiverPositionDx);
    builder.write(frame::kReceiverPositionDy);
    if (state_.contact)
        builder.write(frame::kContactViewDepth);
    readLitDraws(builder, state_);
    return true;
}

void ReceiverPrepassPass::execute(const FramePassContext& context)
{
    if (state_.contact) {
        // Contact shadows' receiver prepass, which writes the view depth too.
        const rhi::Framebuffer& target =
            context.framebuffer({frame::kReceiverPositionDx, frame::kReceiverPositionDy, frame::kContactViewDepth},
                                frame::kLitDepth);
        state_.stats->depthPrepassDraws +=
            state_.contactShadows->prepass(true).record(context.commands(), target, scene_, state_.litDraws,
                                                        state_.litFrame);
        return;
    }
    state_.stats->depthPrepassDraws +=
        prepass_.record(context.commands(), collection_.receiverTarget(), scene_, state_.litDraws, state_.litFrame);
}

std::string ScreenSpaceShadowsPass::name() const { return std::string(frame::kScreenSpaceShadowsPass); }

bool ScreenSpaceShadowsPass::setup(FramePassBuilder& builder)
{
    if (!state_.screenSpace)
        return false;
    builder.read(frame::kLitDepth);
    builder.read(frame::kReceiverPositionDx);
    builder.read(frame::kReceiverPositionDy);
    readShadowMaps(builder);
    builder.write(frame::kScreenSpaceShadows);
    return true;
}

void ScreenSpaceShadowsPass::execute(const FramePassContext& context)
{
    rhi::CommandList& commands = context.commands();
    const FrameDesc& desc = *state_.desc;
    collection_.begin(commands, state_.features,
                      state_.uniforms->push(
                          screenSpaceShadowUniforms(state_.litFrameUniforms, desc.width, desc.height)));
    commands.bindBindingSet(*state_.shadowMapSet);
    collection_.draw(commands);
}

} // namespace penumbra::render
