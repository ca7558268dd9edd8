#include "DepthPrepass.hpp"

#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace penumbra::render {
namespace {

constexpr std::uint32_t kDepthPrepassLocations[] = {0, 2, 3, 5}; // the mesh attributes depth_prepass.vert reads

std::uint32_t pipelineIndex(bool doubleSided, bool clip) { return (doubleSided ? 1u : 0u) + (clip ? 2u : 0u); }

// receiver_prepass.frag, opaque or with the clip materials' alpha test.
rhi::ShaderSource receiverFragment(bool clip)
{
    rhi::ShaderSource source = litShader("receiver_prepass.frag");
    source.includes.push_back(
        {"receiver_prepass_variant.glsl", fmt::format("#define PENUMBRA_RECEIVER_CLIP {}\n", clip ? 1 : 0)});
    return source;
}

} // namespace

DepthPrepass::DepthPrepass(rhi::Device& device, rhi::Format depthFormat, std::uint32_t samples, bool receivers)
    : samples_(samples), receivers_(receivers),
      vertex_(device.createShader(litShader(receivers ? "receiver_prepass.vert" : "depth_prepass.vert"))),
      // Depth only, no discard: early depth testing stays on.
      opaqueFragment_(
          device.createShader(receivers ? receiverFragment(false) : shaders::load("shadow_caster_opaque.frag"))),
      clipFragment_(device.createShader(receivers ? receiverFragment(true) : litShader("depth_prepass_clip.frag")))
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
    desc.depth = {.test = true, .write = true, .compare = rhi::DepthTest::Nearer};
    for (const bool clip : {false, true})
        for (const bool doubleSided : {false, true}) {
            desc.fragment = clip ? clipFragment_.get() : opaqueFragment_.get();
            desc.cull = doubleSided ? rhi::CullMode::None : rhi::CullMode::Back;
            desc.debugName = fmt::format("depth prepass ({}{}, {}{})", receivers ? "receivers, " : "",
                                         clip ? "clip" : "opaque", doubleSided ? "double-sided" : "culled",
                                         samples > 1 ? fmt::format(", {}x MSAA", samples) : std::string());
            pipelines_[pipelineIndex(doubleSided, clip)] = device.createPipeline(desc);
        }
}

std::uint32_t DepthPrepass::record(rhi::CommandList& commands, const rhi::Framebuffer& target, const GpuScene& gpuScene,
                                   std::span<const LitDraw> draws, const rhi::UniformSlice& frame) const
{
    const scene::Scene& scene = gpuScene.scene();
    commands.beginPass({.framebuffer = &target, .clearColor = std::nullopt, .clearDepth = true});
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
        gpuScene.drawWithMaps(commands, object, kLitMaterialMapBinding, kLitCoverageMapBinding, draw.instances,
                              draw.instanceCount);
        ++issued;
    }
    commands.endPass();
    return issued;
}

} // namespace penumbra::render
