#pragma once

#include "FrameState.hpp"

#include "penumbra/render/FramePass.hpp"

namespace penumbra::render {

// ShadowSettings::culling gpu with instancing: the opaque lit objects tested against the camera's view
// (GpuViewCulling), whose instance lists and indirect draws (frame::kViewCulledInstances, kViewCulledDraws) the depth
// prepasses and the lit passes draw.
class ViewCullingPass final : public FramePass {
public:
    explicit ViewCullingPass(const FrameState& state) : state_(state) {}
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const FrameState& state_;
};

} // namespace penumbra::render
