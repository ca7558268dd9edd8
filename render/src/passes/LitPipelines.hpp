#pragma once

#include "penumbra/rhi/Device.hpp"

#include <array>
#include <cstdint>
#include <memory>

namespace penumbra::render {

// The lit pass's pipelines for one sample count (FrameDesc::msaa): culled or double-sided (glTF doubleSided), opaque
// or alpha-blended over what is drawn (alphaMode BLEND: tested against the opaque depth, not written), and the opaque
// ones after the depth prepass (equal depth test, no depth write, no discard). Each is created when first chosen:
// a driver compiles the whole lit shader for every pipeline (lavapipe takes about half a second each), and most
// frames use two of the six.
class LitPipelines {
public:
    // `fragment` is lit.frag, `prepassedFragment` lit.frag built for after the depth prepass; both must outlive this.
    LitPipelines(rhi::Device& device, const rhi::Shader& vertex, const rhi::Shader& fragment,
                 const rhi::Shader& prepassedFragment, std::uint32_t samples);

    std::uint32_t samples() const { return samples_; }
    const rhi::Pipeline& choose(bool doubleSided, bool blend, bool prepassed);

private:
    std::unique_ptr<rhi::Pipeline> create(bool doubleSided, bool blend, bool prepassed) const;

    rhi::Device& device_;
    const rhi::Shader& vertex_;
    const rhi::Shader& fragment_;
    const rhi::Shader& prepassedFragment_;
    std::uint32_t samples_;
    std::array<std::unique_ptr<rhi::Pipeline>, 4> forward_;   // pipelineIndex in LitPipelines.cpp
    std::array<std::unique_ptr<rhi::Pipeline>, 2> prepassed_; // culled, double-sided
};

} // namespace penumbra::render
