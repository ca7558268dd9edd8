#include "penumbra/render/ReferenceLitPass.hpp"

#include "penumbra/render/FrameResources.hpp"
#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/shadows/DirectionalShadowUniforms.hpp"
#include "penumbra/shadows/InstanceTransform.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace penumbra::render {
namespace {

constexpr std::uint32_t kReferenceLitLocations[] = {0, 1, 2}; // the mesh attributes reference_lit.vert reads

constexpr rhi::Format kColorFormat = rhi::Format::RGBA8;
constexpr rhi::Format kDepthFormat = rhi::Format::D32F;

rhi::ShaderSource referenceShader(std::string_view fileName)
{
    rhi::ShaderSource source = litShader(fileName);
    source.includes.push_back({"reference_block.glsl",
                               shaders::uniformBlockGlsl(kReferenceSplitBlock, kReferenceSplitsBinding, "reference")});
    return source;
}

LitFrameUniforms frameUniforms(const scene::Camera& camera, const FrameDesc& frame, const scene::Scene& scene,
                               const rhi::Conventions& conventions)
{
    const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
    LitFrameUniforms u;
    u.viewProjection = conventions.perspective(camera.fovY, aspect, camera.nearPlane, camera.farPlane) * camera.view();
    u.cameraPosition = glm::vec4(camera.position, 1.0f);
    u.cameraForward = glm::vec4(camera.forward, 0.0f);
    if (!scene.lights.empty()) {
        u.lights[0] = {.color = scene.lights[0].color * scene.lights[0].intensity,
                       .shadowSlot = 0,
                       .direction = glm::normalize(scene.lights[0].direction)};
    }
    u.ambient = glm::vec4(frame.ambient.sky(), 0.0f);
    return u;
}

ReferenceSplitUniforms splitUniforms(const shadows::DirectionalShadowPlan& plan)
{
    ReferenceSplitUniforms u;
    u.cascadeCount = static_cast<int>(plan.splits.count);
    for (std::uint32_t i = 0; i < plan.splits.count && i < 4; ++i)
        u.farDepths[static_cast<int>(i)] = plan.splits.farOf(i);
    if (!plan.shadowSlots.empty() && plan.shadowSlots[0] >= 0)
        u.firstTile = static_cast<int>(plan.lights[static_cast<std::size_t>(plan.shadowSlots[0])].firstTile);
    return u;
}

} // namespace

ReferenceLitPass::ReferenceLitPass(rhi::Device& device, const SceneRenderer& renderer, const scene::Camera& camera,
                                   const FrameDesc& frame)
    : device_(device), renderer_(renderer), camera_(camera), frame_(frame),
      vertex_(device.createShader(referenceShader("reference_lit.vert"))),
      fragment_(device.createShader(referenceShader("reference_lit.frag"))),
      uniforms_(device, "reference lit pass uniforms"), instances_(device, "reference lit pass instances"),
      color_(device.createTexture({.width = frame.width,
                                   .height = frame.height,
                                   .format = kColorFormat,
                                   .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                   .debugName = std::string(kImage)})),
      depth_(device.createTexture({.width = frame.width,
                                   .height = frame.height,
                                   .format = kDepthFormat,
                                   .usage = rhi::TextureUsage::RenderTarget,
                                   .debugName = std::string(kDepth)}))
{
    rhi::PipelineDesc desc;
    desc.vertex = vertex_.get();
    desc.fragment = fragment_.get();
    // Only the attributes reference_lit.vert reads: the validation layer reports attributes a shader does not consume.
    desc.vertexLayout = GpuScene::vertexLayout();
    std::erase_if(desc.vertexLayout.attributes, [](const rhi::VertexAttribute& a) {
        return a.buffer != shadows::kInstanceSlot &&
               std::find(std::begin(kReferenceLitLocations), std::end(kReferenceLitLocations), a.location) ==
                   std::end(kReferenceLitLocations);
    });
    desc.depthFormat = kDepthFormat;
    desc.depth = {.test = true, .write = true, .compare = rhi::DepthTest::Nearer};
    desc.colorTargets = {rhi::ColorTarget{kColorFormat}};
    desc.uniformLayouts = {shaders::uniformLayout(kLitFrameBlock), shaders::uniformLayout(kLitObjectBlock),
                           shaders::uniformLayout(shadows::kDirectionalShadowBlock),
                           shaders::uniformLayout(kReferenceSplitBlock)};
    for (const bool doubleSided : {false, true}) {
        desc.cull = doubleSided ? rhi::CullMode::None : rhi::CullMode::Back;
        desc.debugName = fmt::format("reference lit ({})", doubleSided ? "double-sided" : "culled");
        pipelines_[doubleSided ? 1 : 0] = device.createPipeline(desc);
    }
}

bool ReferenceLitPass::setup(FramePassBuilder& builder)
{
    if (!enabled_)
        return false;
    builder.read(frame::kDirectionalAtlas);
    if (!renderer_.gpuScene().scene().rig.deformers.empty())
        builder.read(frame::kPosedVertices, ResourceUse::VertexRead);
    builder.write(kImage);
    builder.write(kDepth);
    return true;
}

void ReferenceLitPass::execute(const FramePassContext& context)
{
    const GpuScene& gpuScene = renderer_.gpuScene();
    const scene::Scene& scene = gpuScene.scene();
    uniforms_.reset();
    instances_.reset();
    const rhi::UniformSlice frameSlice = uniforms_.push(frameUniforms(camera_, frame_, scene, device_.conventions()));
    const rhi::UniformSlice shadowSlice = uniforms_.push(renderer_.plan().uniforms);
    const rhi::UniformSlice splitSlice = uniforms_.push(splitUniforms(renderer_.plan()));
    rhi::CommandList& commands = context.commands();
    commands.beginPass(
        {.framebuffer = &context.framebuffer({kImage}, kDepth), .clearColor = glm::vec4(0.2f, 0.22f, 0.26f, 1.0f)});
    const rhi::Pipeline* bound = nullptr;
    for (const scene::Object& object : scene.objects) {
        if (object.castShadows == scene::ShadowCasting::ShadowsOnly)
            continue;
        const scene::Material& material = scene.materialOf(object);
        const rhi::Pipeline* pipeline = pipelines_[material.doubleSided ? 1 : 0].get();
        if (pipeline != bound) {
            commands.bindPipeline(*pipeline);
            rhi::bindUniform(commands, kLitFrameBinding, frameSlice);
            rhi::bindUniform(commands, kLitShadowBinding, shadowSlice);
            rhi::bindUniform(commands, kReferenceSplitsBinding, splitSlice);
            commands.bindTexture(kLitAtlasBinding, context.texture(frame::kDirectionalAtlas),
                                 renderer_.atlas().sampler());
            bound = pipeline;
        }
        // A draw per object, as the public samples draw.
        rhi::bindUniform(commands, kLitObjectBinding,
                         uniforms_.push(LitObjectUniforms{.baseColor = material.baseColor}));
        gpuScene.drawWithMaps(commands, object, kLitMaterialMapBinding, kLitCoverageMapBinding,
                              instances_.push(shadows::instanceTransform(object.transform)), 1);
    }
    commands.endPass();
}

} // namespace penumbra::render
