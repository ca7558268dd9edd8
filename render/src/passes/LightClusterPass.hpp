#pragma once

#include "FrameState.hpp"

#include "penumbra/render/FramePass.hpp"

namespace penumbra::render {

// ShadowSettings local.clusterBuild gpu: the lit pass's clustered light lists built by compute dispatches
// (shadows::GpuLightClusters) into the light cluster and light index textures, which the lit pass and its views read
// as they read the lists built on the CPU.
class LightClusterPass final : public FramePass {
public:
    explicit LightClusterPass(const FrameState& state) : state_(state) {}
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const FrameState& state_;
};

} // namespace penumbra::render
