#pragma once

#include "LitDraws.hpp"

#include "penumbra/render/GpuScene.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/UniformArena.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <span>

namespace penumbra::render {

// The receiver prepass's derivative targets: full float, the lit pass's own values.
inline constexpr rhi::Format kReceiverDerivativeFormat = rhi::Format::RGBA32F;
// The view depth target that contact shadows march through (shaders/view_depth.glsl): full float, 0 where no surface.
inline constexpr rhi::Format kViewDepthFormat = rhi::Format::R32F;

// The depth prepass: opaque and clip objects depth-only, clip ones cut with the lit pass's alpha, so that the lit
// pass after it (equal depth test, no depth write, no discard) shades each visible pixel once, however many leaf
// cards overlap it. Blended objects are not drawn: they blend over the opaque depth in the lit pass.
class DepthPrepass {
public:
    // `samples`: the depth target's sample count (FrameDesc::msaa); each sample's depth is the one the lit pass
    // tests against, so the prepass rasterizes with the lit pass's samples. With `receivers` (the screen-space
    // shadow path) it also writes the world position's screen derivatives, dFdxFine and dFdyFine as lit.frag takes
    // them, into two kReceiverDerivativeFormat colour targets (receiver_prepass.frag). With `viewDepth` (contact
    // shadows) it also writes each pixel's view depth into a kViewDepthFormat colour target after those, cleared to 0
    // (view_depth.glsl).
    DepthPrepass(rhi::Device& device, rhi::Format depthFormat, std::uint32_t samples, bool receivers = false,
                 bool viewDepth = false);

    std::uint32_t samples() const { return samples_; }
    bool receivers() const { return receivers_; }
    bool viewDepth() const { return viewDepth_; }

    // Clears `target` (depth, and the view depth target with viewDepth) and records the draws that are not blended;
    // `frame` is the lit pass's Frame block (shaders/lit.glsl). Returns the draws issued.
    std::uint32_t record(rhi::CommandList& commands, const rhi::Framebuffer& target, const GpuScene& scene,
                         std::span<const LitDraw> draws, const rhi::UniformSlice& frame) const;

private:
    std::uint32_t samples_;
    bool receivers_;
    bool viewDepth_;
    std::unique_ptr<rhi::Shader> vertex_, opaqueFragment_, clipFragment_;
    // Culled or not (glTF doubleSided), opaque or clip (pipelineIndex in DepthPrepass.cpp).
    std::array<std::unique_ptr<rhi::Pipeline>, 4> pipelines_;
};

} // namespace penumbra::render
