#pragma once

#include "FrameState.hpp"
#include "penumbra/render/FramePass.hpp"

namespace penumbra::render {

class DepthReduction;

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
