#pragma once

#include "FrameState.hpp"
#include "penumbra/render/FramePass.hpp"

namespace penumbra::render {

class DepthPrepass;
class DepthReduction;
class GpuScene;

// ShadowSettings's depth fit with MSAA on the forward path: the lit pass's depth is multisampled, so a single-sampled
// depth prepass into the lit depth gives the reduction its pixels (the screen-space path's receiver prepass already
// does, and without MSAA the depth prepass or the lit pass).
class DepthFitPrepassPass final : public FramePass {
public:
    DepthFitPrepassPass(const FrameState& state, const DepthPrepass* prepass, const GpuScene& scene)
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

// The depth fit's reduction of the single-sampled lit depth (DepthReduction), after the lit pass; the renderer reads
// its result after the submission, for the next frame's plan.
class DepthReductionPass final : public FramePass {
public:
    DepthReductionPass(const FrameState& state, DepthReduction* reduction) : state_(state), reduction_(reduction) {}

    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const FrameState& state_;
    DepthReduction* reduction_; // made by the first depth-fit frame
};

} // namespace penumbra::render
