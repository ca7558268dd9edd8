#pragma once

#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/shadows/DirectionalShadowUniforms.hpp"
#include "penumbra/shadows/LocalShadowUniforms.hpp"
#include "penumbra/shadows/StaticShadowPlanner.hpp"

#include <cstdint>
#include <memory>
#include <unordered_map>

namespace penumbra::render {

// The lit pass's pipelines for one sample count (FrameDesc::msaa): culled or double-sided (glTF doubleSided), opaque
// or alpha-blended over what is drawn (alphaMode BLEND: tested against the opaque depth, not written), and the opaque
// ones after the depth prepass (equal depth test, no depth write, no discard); each for the shader features it is
// asked for (LitShaderFeatures), created when first chosen: a driver compiles the whole lit shader for every pipeline
// (lavapipe takes about half a second each), and most frames use few of them.
class LitPipelines {
public:
    // `shadowMaps`: the layout of the shadow maps' binding set (ShadowMapBindings), which the pipelines list.
    LitPipelines(rhi::Device& device, const rhi::Shader& vertex, const rhi::BindingSetLayout& shadowMaps,
                 std::uint32_t samples);

    std::uint32_t samples() const { return samples_; }
    // A blended draw takes the forward shader whatever features.depthPrepassed says.
    const rhi::Pipeline& choose(LitShaderFeatures features, bool doubleSided, bool blend);

private:
    const rhi::Shader& fragment(const LitShaderFeatures& features);

    rhi::Device& device_;
    const rhi::Shader& vertex_;
    const rhi::BindingSetLayout& shadowMaps_;
    std::uint32_t samples_;
    std::unordered_map<std::uint32_t, std::unique_ptr<rhi::Shader>> fragments_; // by featureKey
    std::unordered_map<std::uint32_t, std::unique_ptr<rhi::Pipeline>> pipelines_; // by featureKey, sides, blend
};

// The features a frame's lights and shadow maps need, read from what the lit shader reads (the lit pass's own view,
// no prepass and every material map: the caller sets those).
LitShaderFeatures frameShaderFeatures(const LitFrameUniforms& frame,
                                      const shadows::DirectionalShadowUniforms& directional,
                                      const shadows::LocalShadowPlan& local,
                                      const shadows::StaticShadowPlan& staticPlan);

} // namespace penumbra::render
