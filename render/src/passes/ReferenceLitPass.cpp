#include "penumbra/render/ReferenceLitPass.hpp"

#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/shadows/DirectionalShadowUniforms.hpp"
#include "penumbra/shadows/InstanceTransform.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace penumbra::render {
namespace {

constexpr std::uint32_t kLocations[] = {0, 1, 2}; // the mesh attributes reference_lit.vert reads

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

ReferenceLitPass::ReferenceLitPass(rhi::Device& device, const GpuScene& scene)
    : device_(device), scene_(scene), vertex_(device.createShader(referenceShader("reference_lit.vert"))),
      fragment_(device.createShader(referenceShader("reference_lit.frag"))), commands_(device.createCommandList()),
      timestamps_(device.capabilities().timestamps ? device.createTimestampQueries(2) : nullptr),
      uniforms_(device, "reference lit pass uniforms"), instances_(device, "reference lit pass instances")
{
    rhi::PipelineDesc desc;
    desc.vertex = vertex_.get();
    desc.fragment = fragment_.get();
    // Only the attributes reference_lit.vert reads: the validation layer reports attributes a shader does not consume.
    desc.vertexLayout = GpuScene::vertexLayout();
    std::erase_if(desc.vertexLayout.attributes, [](const rhi::VertexAttribute& a) {
        return a.buffer != shadows::kInstanceSlot &&
               std::find(std::begin(kLocations), std::end(kLocations), a.location) == std::end(kLocations);
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

double ReferenceLitPass::render(const scene::Camera& camera, const FrameDesc& frame, const SceneRenderer& renderer)
{
    if (!color_ || color_->desc().width != frame.width || color_->desc().height != frame.height) {
        color_ = device_.createTexture({.width = frame.width,
                                        .height = frame.height,
                                        .format = kColorFormat,
                                        .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                        .debugName = "reference lit image"});
        depth_ = device_.createTexture({.width = frame.width,
                                        .height = frame.height,
                                        .format = kDepthFormat,
                                        .usage = rhi::TextureUsage::RenderTarget,
                                        .debugName = "reference lit depth"});
        const rhi::Attachment color{color_.get(), 0};
        target_ = device_.createFramebuffer(
            {.colors = {&color, 1}, .depth = {depth_.get(), 0}, .debugName = "reference lit"});
    }
    const scene::Scene& scene = scene_.scene();
    uniforms_.reset();
    instances_.reset();
    const rhi::UniformSlice frameSlice = uniforms_.push(frameUniforms(camera, frame, scene, device_.conventions()));
    const rhi::UniformSlice shadowSlice = uniforms_.push(renderer.plan().uniforms);
    const rhi::UniformSlice splitSlice = uniforms_.push(splitUniforms(renderer.plan()));
    rhi::CommandList& commands = *commands_;
    if (timestamps_)
        commands.writeTimestamp(*timestamps_, 0);
    commands.beginPass({.framebuffer = target_.get(), .clearColor = glm::vec4(0.2f, 0.22f, 0.26f, 1.0f)});
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
            commands.bindTexture(kLitAtlasBinding, renderer.atlas().texture(), renderer.atlas().sampler());
            bound = pipeline;
        }
        // A draw per object, as the public samples draw.
        rhi::bindUniform(commands, kLitObjectBinding,
                         uniforms_.push(LitObjectUniforms{.baseColor = material.baseColor}));
        scene_.drawWithMaps(commands, object, kLitMaterialMapBinding, kLitCoverageMapBinding,
                            instances_.push(shadows::instanceTransform(object.transform)), 1);
    }
    commands.endPass();
    if (timestamps_)
        commands.writeTimestamp(*timestamps_, 1);
    device_.submit(commands);
    if (!timestamps_)
        return 0.0;
    const std::vector<double> ns = device_.readTimestamps(*timestamps_);
    return (ns[1] - ns[0]) * 1e-6;
}

} // namespace penumbra::render
