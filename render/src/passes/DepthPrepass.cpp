#include "DepthPrepass.hpp"

#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace penumbra::render {
namespace {

constexpr std::uint32_t kDepthPrepassLocations[] = {0, 2, 3, 5}; // the mesh attributes depth_prepass.vert reads

std::uint32_t pipelineIndex(bool doubleSided, bool clip) { return (doubleSided ? 1u : 0u) + (clip ? 2u : 0u); }

// receiver_prepass.frag, opaque or with the clip materials' alpha test, with the view depth or without.
rhi::ShaderSource receiverFragment(bool clip, bool viewDepth)
{
    rhi::ShaderSource source = litShader("receiver_prepass.frag");
    source.includes.push_back(
        {"receiver_prepass_variant.glsl",
         fmt::format("#define PENUMBRA_RECEIVER_CLIP {}\n#define PENUMBRA_RECEIVER_VIEW_DEPTH {}\n", clip ? 1 : 0,
                     viewDepth ? 1 : 0)});
    return source;
}

// view_depth_prepass.frag, opaque or with the clip materials' alpha test.
rhi::ShaderSource viewDepthFragment(bool clip)
{
    rhi::ShaderSource source = litShader("view_depth_prepass.frag");
    source.includes.push_back(
        {"view_depth_prepass_variant.glsl", fmt::format("#define PENUMBRA_VIEW_DEPTH_CLIP {}\n", clip ? 1 : 0)});
    return source;
}

// The prepass's fragment shader for its targets, opaque or clip.
rhi::ShaderSource prepassFragment(bool receivers, bool viewDepth, bool clip)
{
    if (receivers)
        return receiverFragment(clip, viewDepth);
    if (viewDepth)
        return viewDepthFragment(clip);
    // Depth only, no discard: early depth testing stays on.
    return clip ? litShader("depth_prepass_clip.frag") : shaders::load("shadow_caster_opaque.frag");
}

} // namespace

DepthPrepass::DepthPrepass(rhi::Device& device, rhi::Format depthFormat, std::uint32_t samples, bool receivers,
                           bool viewDepth)
    : samples_(samples), receivers_(receivers), viewDepth_(viewDepth),
      vertex_(device.createShader(litShader(receivers ? "receiver_prepass.vert" : "depth_prepass.vert"))),
      opaqueFragment_(device.createShader(prepassFragment(receivers, viewDepth, false))),
      clipFragment_(device.createShader(prepassFragment(receivers, viewDepth, true)))
{
    rhi::PipelineDesc desc;
    desc.vertex = vertex_.get();
    // Only the attributes depth_prepass.vert reads: the validation layer reports attributes a shader does not consume.
    desc.vertexLayout = GpuScene::vertexLayout();
    std::erase_if(desc.vertexLayout.attributes, [](const rhi::VertexAttribute& a) {
        return a.buffer != shadows::kInstanceSlot &&
               std::find(std::begin(kDepthPrepassLocations), std::end(kDepthPrepassLocations), a.location) ==
                   std::end(kDepthPrepassLocations);
    });
    desc.depthFormat = depthFormat;
    desc.samples = samples;
    if (receivers)
        desc.colorTargets = {rhi::ColorTarget{kReceiverDerivativeFormat}, rhi::ColorTarget{kReceiverDerivativeFormat}};
    if (viewDepth)
        desc.colorTargets.push_back(rhi::ColorTarget{kViewDepthFormat});
    desc.depth = {.test = true, .write = true, .compare = rhi::DepthTest::Nearer};
    for (const bool clip : {false, true})
        for (const bool doubleSided : {false, true}) {
            desc.fragment = clip ? clipFragment_.get() : opaqueFragment_.get();
            desc.cull = doubleSided ? rhi::CullMode::None : rhi::CullMode::Back;
            desc.debugName = fmt::format("depth prepass ({}{}{}, {}{})", receivers ? "receivers, " : "",
                                         viewDepth ? "view depth, " : "", clip ? "clip" : "opaque",
                                         doubleSided ? "double-sided" : "culled",
                                         samples > 1 ? fmt::format(", {}x MSAA", samples) : std::string());
            pipelines_[pipelineIndex(doubleSided, clip)] = device.createPipeline(desc);
        }
}

std::uint32_t DepthPrepass::record(rhi::CommandList& commands, const rhi::Framebuffer& target, const GpuScene& gpuScene,
                                   std::span<const LitDraw> draws, const rhi::UniformSlice& frame) const
{
    const scene::Scene& scene = gpuScene.scene();
    // The view depth's 0 marks pixels without a surface; the derivatives beside it are read only where there is one.
    commands.beginPass({.framebuffer = &target,
                        .clearColor = viewDepth_ ? std::optional(glm::vec4(0.0f)) : std::nullopt,
                        .clearDepth = true});
    const rhi::Pipeline* bound = nullptr;
    std::uint32_t issued = 0;
    for (const LitDraw& draw : draws) {
        const scene::Object& object = scene.objects[draw.object];
        const scene::Material& material = scene.materialOf(object);
        if (material.blend)
            continue;
        const bool clip = material.caster == scene::CasterMode::Clip;
        const rhi::Pipeline* pipeline = pipelines_[pipelineIndex(material.doubleSided, clip)].get();
        if (pipeline != bound) {
            commands.bindPipeline(*pipeline);
            rhi::bindUniform(commands, kLitFrameBinding, frame);
            bound = pipeline;
        }
        rhi::bindUniform(commands, kLitObjectBinding, draw.uniforms);
        // lit.glsl declares every material map; the RHI asks for all of them bound.
        recordLitDraw(commands, gpuScene, draw);
        ++issued;
    }
    commands.endPass();
    return issued;
}

} // namespace penumbra::render
