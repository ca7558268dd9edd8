#pragma once

#include "FrameState.hpp"

#include "penumbra/render/FramePass.hpp"

namespace penumbra::render {

class DepthPrepass;
class GpuScene;
class ScreenSpaceShadowPass;

// With MSAA on the forward path, a single-sampled depth prepass into the lit depth for the passes that read depth per
// pixel centre: the depth fit's reduction and the contact shadows' march, whose view depth it writes then (the RHI
// samples no multisampled depth; the screen-space path's receiver prepass already draws it).
class SingleSampledDepthPass final : public FramePass {
public:
    SingleSampledDepthPass(const FrameState& state, const DepthPrepass* prepass, const GpuScene& scene)
        : state_(state), prepass_(prepass), scene_(scene)
    {
    }
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const FrameState& state_;
    const DepthPrepass* prepass_; // made by the first frame that needs it
    const GpuScene& scene_;
};

// The lit pass's depth first (DepthPrepass): into the multisampled depth with MSAA, else into the lit depth (and with
// contact shadows their view depth, ContactShadowPass::prepass); the screen-space path without MSAA takes the receiver
// prepass instead.
class DepthPrepassPass final : public FramePass {
public:
    DepthPrepassPass(const FrameState& state, const DepthPrepass& prepass, const GpuScene& scene)
        : state_(state), prepass_(prepass), scene_(scene)
    {
    }
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    bool writesViewDepth() const { return state_.contact && !state_.multisampled; }

    const FrameState& state_;
    const DepthPrepass& prepass_;
    const GpuScene& scene_;
};

// The screen-space path's single-sampled prepass with receivers: the lit depth and the world position's screen
// derivatives that the collection reads, and with contact shadows their view depth.
class ReceiverPrepassPass final : public FramePass {
public:
    ReceiverPrepassPass(const FrameState& state, const DepthPrepass& prepass, const ScreenSpaceShadowPass& collection,
                        const GpuScene& scene)
        : state_(state), prepass_(prepass), collection_(collection), scene_(scene)
    {
    }
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const FrameState& state_;
    const DepthPrepass& prepass_;
    const ScreenSpaceShadowPass& collection_;
    const GpuScene& scene_;
};

// The screen-space collection of the directional lights' shadows (ScreenSpaceShadowPass).
class ScreenSpaceShadowsPass final : public FramePass {
public:
    ScreenSpaceShadowsPass(const FrameState& state, ScreenSpaceShadowPass& collection)
        : state_(state), collection_(collection)
    {
    }
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const FrameState& state_;
    ScreenSpaceShadowPass& collection_;
};

} // namespace penumbra::render
