#pragma once

#include "penumbra/render/GpuScene.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/UniformArena.hpp"
#include "penumbra/shaders/ShaderBlock.hpp"

#include <array>
#include <cstdint>
#include <memory>

namespace penumbra::render {

inline constexpr std::uint32_t kReferenceSplitsBinding = 4;

// The reference block ReferenceSplits of shaders/reference_lit.frag (generated into reference_block.glsl).
struct ReferenceSplitUniforms {
    std::int32_t cascadeCount = 0;
    std::int32_t firstTile = -1; // the first directional light's first atlas tile (-1: no shadows)
    alignas(16) glm::vec4 farDepths{0.0f}; // view depth where cascade i ends
};

inline constexpr std::array kReferenceSplitFields{
    PENUMBRA_SHADER_FIELD(ReferenceSplitUniforms, cascadeCount),
    PENUMBRA_SHADER_FIELD(ReferenceSplitUniforms, firstTile),
    PENUMBRA_SHADER_FIELD(ReferenceSplitUniforms, farDepths),
};
inline constexpr shaders::ShaderStruct kReferenceSplitBlock{"ReferenceSplits", sizeof(ReferenceSplitUniforms),
                                                            kReferenceSplitFields};
static_assert(shaders::matchesLayout(kReferenceSplitBlock, shaders::BlockLayout::Std140));

// The floor a lit pass is measured against (penumbra bench): the lit shader of the public cascaded shadow map
// samples (Sascha Willems' Vulkan examples, "shadowmappingcascade"; LearnOpenGL, "Cascaded Shadow Mapping"), drawn
// on the renderer's scene, meshes and directional atlas: vertex transform, one base colour texture sample with an
// alpha test at 0.5, the cascade chosen by view depth against the split distances, one nearest comparison in the
// atlas, Lambert n.l of the first directional light plus ambient; forward, no prepass, into targets of its own.
class ReferenceLitPass {
public:
    // Builds the pass's pipeline for the scene's meshes on `device`.
    ReferenceLitPass(rhi::Device& device, const GpuScene& scene);

    // Draws the camera's view with the renderer's last plan and atlas (after SceneRenderer::render) in one
    // submission; returns its GPU time in milliseconds (0 on a device without timestamps).
    double render(const scene::Camera& camera, const FrameDesc& frame, const SceneRenderer& renderer);

    // The picture the last render() drew.
    const rhi::Texture& image() const { return *color_; }

private:
    rhi::Device& device_;
    const GpuScene& scene_;
    std::unique_ptr<rhi::Shader> vertex_, fragment_;
    std::array<std::unique_ptr<rhi::Pipeline>, 2> pipelines_; // culled, double-sided
    std::unique_ptr<rhi::CommandList> commands_;
    std::unique_ptr<rhi::TimestampQueries> timestamps_;
    rhi::UniformArena uniforms_;
    rhi::VertexArena instances_;
    std::unique_ptr<rhi::Texture> color_, depth_;
    std::unique_ptr<rhi::Framebuffer> target_;
};

} // namespace penumbra::render
