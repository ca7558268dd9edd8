#pragma once

#include "penumbra/render/FramePass.hpp"
#include "penumbra/render/GpuScene.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/UniformArena.hpp"
#include "penumbra/shaders/ShaderBlock.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

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
//
// A pass of the frame graph, timed as every pass is (FrameStats::passMs(kName)). Its two targets are the
// application's textures: add them and the pass to the renderer, after the lit pass, as penumbra bench does:
//     auto reference = std::make_shared<ReferenceLitPass>(device, renderer, camera, frame);
//     renderer.addTexture(std::string(ReferenceLitPass::kImage), reference->image());
//     renderer.addTexture(std::string(ReferenceLitPass::kDepth), reference->depth());
//     renderer.addPass(reference, PassPlacement::after(std::string(frame::kLitPass)));
class ReferenceLitPass final : public FramePass {
public:
    static constexpr std::string_view kName = "reference lit";
    static constexpr std::string_view kImage = "reference lit image";
    static constexpr std::string_view kDepth = "reference lit depth";

    // Builds the pass's pipeline for the renderer's scene and its targets at the frame's size; it draws `camera`'s
    // view of the frames like `frame` (its size and ambient light) with the renderer's plan and atlas. The renderer
    // must outlive the pass.
    ReferenceLitPass(rhi::Device& device, const SceneRenderer& renderer, const scene::Camera& camera,
                     const FrameDesc& frame);

    // Whether the pass runs in the frames from the next one on (it does from the start).
    void setEnabled(bool enabled) { enabled_ = enabled; }

    std::string name() const override { return std::string(kName); }
    bool setup(FramePassBuilder& builder) override;
    void execute(const FramePassContext& context) override;

    // The picture the pass draws (kImage), and its depth (kDepth).
    const rhi::Texture& image() const { return *color_; }
    const rhi::Texture& depth() const { return *depth_; }

private:
    rhi::Device& device_;
    const SceneRenderer& renderer_;
    scene::Camera camera_;
    FrameDesc frame_;
    bool enabled_ = true;
    std::unique_ptr<rhi::Shader> vertex_, fragment_;
    std::array<std::unique_ptr<rhi::Pipeline>, 2> pipelines_; // culled, double-sided
    rhi::UniformArena uniforms_;
    rhi::VertexArena instances_;
    std::unique_ptr<rhi::Texture> color_, depth_;
};

} // namespace penumbra::render
