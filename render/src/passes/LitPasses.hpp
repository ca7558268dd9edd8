#pragma once

#include "FrameState.hpp"

#include "penumbra/render/FramePass.hpp"

namespace penumbra::render {

class GpuScene;
class LitPipelines;
class ScreenSpaceShadowPass;

// The lit pass: every lit draw shaded with the frame's lights and shadows, into the multisampled colour with MSAA,
// else into the lit image; after the depth prepass it tests the prepass's depth for equality.
class LitPass final : public FramePass {
public:
    LitPass(const FrameState& state, LitPipelines& pipelines, const GpuScene& scene,
            const ScreenSpaceShadowPass* collection)
        : state_(state), pipelines_(pipelines), scene_(scene), collection_(collection)
    {
    }
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    LitShaderFeatures features() const;
    bool readsPixelDepth(const LitShaderFeatures& f) const;

    const FrameState& state_;
    LitPipelines& pipelines_;
    const GpuScene& scene_;
    const ScreenSpaceShadowPass* collection_; // the screen-space path's, or nullptr
};

// FrameDesc::msaa > 1: the multisampled colour averaged into the lit image.
class ResolvePass final : public FramePass {
public:
    ResolvePass(const FrameState& state, rhi::Texture& litImage) : state_(state), litImage_(litImage) {}
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const FrameState& state_;
    rhi::Texture& litImage_; // the resolve's destination, frame::kLitImage
};

// A debug view of the lit pass, single-sampled, without the prepass, with forward shadows, into its own image over
// the cleared lit depth: the lit picture tinted by cascade (FrameDesc::cascadeView), or one light's raw shadow-map
// visibility (FrameDesc::visibilityOf). Culled where the frame does not ask for its image.
class LitViewPass final : public FramePass {
public:
    LitViewPass(const FrameState& state, LitPipelines& pipelines, const GpuScene& scene, LitView view)
        : state_(state), pipelines_(pipelines), scene_(scene), view_(view)
    {
    }
    std::string name() const override;
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

private:
    const FrameState& state_;
    LitPipelines& pipelines_;
    const GpuScene& scene_;
    LitView view_;
};

} // namespace penumbra::render
