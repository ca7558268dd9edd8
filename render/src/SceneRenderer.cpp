#include "penumbra/render/SceneRenderer.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace penumbra::render {
namespace {

constexpr std::uint32_t kFrameBinding = 0;
constexpr std::uint32_t kObjectBinding = 1;
constexpr std::uint32_t kShadowBinding = 2;
constexpr std::uint32_t kAtlasBinding = 3;
constexpr rhi::Format kLitFormat = rhi::Format::RGBA8;
constexpr rhi::Format kDepthFormat = rhi::Format::D32F;
constexpr glm::vec4 kBackground{0.2f, 0.22f, 0.26f, 1.0f}; // sRGB-encoded, as the lit shader writes

shadows::ShadowCamera shadowCamera(const scene::Camera& camera, float aspect)
{
    const glm::vec3 up = glm::normalize(glm::cross(camera.right(), camera.forward));
    return {camera.position, camera.forward, up, camera.fovY, aspect, camera.nearPlane, camera.farPlane};
}

std::vector<shadows::DirectionalShadowLightInput> shadowLights(const std::vector<scene::DirectionalLight>& lights)
{
    std::vector<shadows::DirectionalShadowLightInput> inputs;
    for (const scene::DirectionalLight& light : lights)
        inputs.push_back({light.direction, light.shadowStrength, light.nearPlaneOffset, light.normalBias,
                          light.slopeScaleBias, true});
    return inputs;
}

LitObjectUniforms objectUniforms(const scene::Object& object, const scene::Material& material)
{
    return {object.transform,
            glm::transpose(glm::inverse(object.transform)),
            material.baseColor,
            {material.metallic, material.roughness, material.alphaCutoff, static_cast<float>(material.caster)},
            {material.receiveShadows ? 1 : 0, 0, 0, 0}};
}

std::unique_ptr<rhi::Texture> colorTarget(rhi::Device& device, const FrameDesc& frame, const std::string& name)
{
    return device.createTexture({.width = frame.width,
                                 .height = frame.height,
                                 .format = kLitFormat,
                                 .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                 .debugName = name});
}

} // namespace

SceneRenderer::SceneRenderer(rhi::Device& device, const scene::Scene& scene)
    : device_(device), gpuScene_(device, scene), shadowPass_(device, GpuScene::vertexFormat()),
      litVertex_(device.createShader(shaders::load("lit.vert"))),
      litFragment_(device.createShader(shaders::load("lit.frag"))), commands_(device.createCommandList()),
      timestamps_(device.capabilities().timestamps ? device.createTimestampQueries(3) : nullptr),
      uniforms_(device, "lit pass uniforms")
{
    const shadows::CasterVertexFormat vertex = GpuScene::vertexFormat();
    rhi::PipelineDesc desc;
    desc.vertex = litVertex_.get();
    desc.fragment = litFragment_.get();
    desc.vertexLayout = {{{vertex.stride, false}},
                         {{0, rhi::VertexFormat::Float3, vertex.positionOffset, 0},
                          {1, rhi::VertexFormat::Float3, static_cast<std::uint32_t>(offsetof(scene::Vertex, normal)), 0},
                          {2, rhi::VertexFormat::Float2, vertex.uvOffset, 0}}};
    desc.cull = rhi::CullMode::Back;
    desc.depth = {.test = true, .write = true, .compare = rhi::DepthTest::Nearer};
    desc.colorTargets = {{kLitFormat}};
    desc.depthFormat = kDepthFormat;
    desc.debugName = "lit";
    litPipeline_ = device.createPipeline(desc);
}

void SceneRenderer::prepareTargets(const FrameDesc& frame)
{
    if (frame.width == 0 || frame.height == 0)
        throw rhi::Error(fmt::format("frame size {}x{}: width and height must be at least 1", frame.width, frame.height));
    const shadows::DirectionalShadowSettings& directional = frame.shadows.directional;
    if (!atlas_ || atlas_->size() != directional.atlasSize || atlas_->format() != directional.atlasFormat)
        atlas_ = std::make_unique<shadows::ShadowAtlas>(device_, directional.atlasSize, directional.atlasFormat,
                                                        "directional shadow atlas");
    if (lit_ && lit_->desc().width == frame.width && lit_->desc().height == frame.height)
        return;
    lit_ = colorTarget(device_, frame, "lit image");
    cascades_ = colorTarget(device_, frame, "cascade view");
    depth_ = device_.createTexture({.width = frame.width,
                                    .height = frame.height,
                                    .format = kDepthFormat,
                                    .usage = rhi::TextureUsage::RenderTarget,
                                    .debugName = "lit depth"});
    const rhi::Attachment litColor{lit_.get(), 0};
    const rhi::Attachment cascadeColor{cascades_.get(), 0};
    litTarget_ = device_.createFramebuffer({.colors = {&litColor, 1}, .depth = {depth_.get(), 0}, .debugName = "lit"});
    cascadeTarget_ = device_.createFramebuffer(
        {.colors = {&cascadeColor, 1}, .depth = {depth_.get(), 0}, .debugName = "cascade view"});
}

LitFrameUniforms SceneRenderer::frameUniforms(const scene::Camera& camera, const FrameDesc& frame, LitView view) const
{
    const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
    const rhi::Conventions& conventions = device_.conventions();
    LitFrameUniforms u;
    u.viewProjection = conventions.perspective(camera.fovY, aspect, camera.nearPlane, camera.farPlane) * camera.view();
    u.cameraPosition = glm::vec4(camera.position, 1.0f);
    u.cameraForward = glm::vec4(camera.forward, 0.0f);
    const std::vector<scene::DirectionalLight>& lights = gpuScene_.scene().lights;
    const auto count = static_cast<std::uint32_t>(std::min<std::size_t>(lights.size(), maxLitDirectionalLights));
    for (std::uint32_t i = 0; i < count; ++i) {
        u.lightColor[i] = glm::vec4(lights[i].color * lights[i].intensity, 0.0f);
        u.lightDirection[i] = glm::vec4(glm::normalize(lights[i].direction), static_cast<float>(plan_.shadowSlots[i]));
    }
    u.ambient = glm::vec4(frame.ambient, 0.0f);
    u.config = {static_cast<int>(count), static_cast<int>(view), 0, 0};
    return u;
}

void SceneRenderer::recordLitPass(rhi::CommandList& commands, const rhi::Framebuffer& target,
                                  const LitFrameUniforms& frame, const rhi::UniformSlice& shadowUniforms)
{
    const scene::Scene& scene = gpuScene_.scene();
    commands.beginPass({.framebuffer = &target, .clearColor = kBackground});
    commands.bindPipeline(*litPipeline_);
    rhi::bindUniform(commands, kFrameBinding, uniforms_.push(frame));
    rhi::bindUniform(commands, kShadowBinding, shadowUniforms);
    commands.bindTexture(kAtlasBinding, atlas_->texture(), atlas_->sampler());
    for (const scene::Object& object : scene.objects) {
        rhi::bindUniform(commands, kObjectBinding, uniforms_.push(objectUniforms(object, scene.materialOf(object))));
        commands.bindVertexBuffer(0, gpuScene_.vertices(object.mesh));
        commands.bindIndexBuffer(gpuScene_.indices(object.mesh), rhi::IndexType::UInt32);
        commands.drawIndexed(static_cast<std::uint32_t>(scene.meshOf(object).indices.size()));
    }
    commands.endPass();
}

FrameStats SceneRenderer::render(const scene::Camera& camera, const FrameDesc& frame)
{
    prepareTargets(frame);
    const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
    const scene::Scene& scene = gpuScene_.scene();
    const std::vector<shadows::Bounds> bounds = gpuScene_.casterBounds();
    const std::vector<shadows::DirectionalShadowLightInput> lights = shadowLights(scene.lights);
    plan_ = shadows::planDirectionalShadows(frame.shadows, device_.conventions(), shadowCamera(camera, aspect), lights,
                                            bounds);
    notes_.clear();
    for (const shadows::ShadowPlanNote& note : plan_.report)
        notes_.push_back(note.lightIndex ? fmt::format("light {} ('{}') has no shadows: {}", *note.lightIndex,
                                                       scene.lights[*note.lightIndex].name, note.reason)
                                         : fmt::format("no shadows: {}", note.reason));
    for (std::size_t i = maxLitDirectionalLights; i < scene.lights.size(); ++i)
        notes_.push_back(fmt::format("light {} ('{}') is not drawn: beyond the limit of {} directional lights", i,
                                     scene.lights[i].name, maxLitDirectionalLights));

    FrameStats stats;
    for (const shadows::ShadowedDirectionalLight& light : plan_.lights)
        for (const shadows::DirectionalCascadePlan& cascade : light.cascades)
            stats.casterDrawsWithoutCullingBias += cascade.casters.overlapping;

    uniforms_.reset();
    const rhi::UniformSlice shadowUniforms = uniforms_.push(plan_.uniforms);
    rhi::CommandList& commands = *commands_;
    if (timestamps_)
        commands.writeTimestamp(*timestamps_, 0);
    stats.casterDraws = shadowPass_.record(commands, *atlas_, plan_, gpuScene_.casters());
    if (timestamps_)
        commands.writeTimestamp(*timestamps_, 1);
    recordLitPass(commands, *litTarget_, frameUniforms(camera, frame, LitView::Lit), shadowUniforms);
    if (timestamps_)
        commands.writeTimestamp(*timestamps_, 2);
    if (frame.cascadeView)
        recordLitPass(commands, *cascadeTarget_, frameUniforms(camera, frame, LitView::Cascades), shadowUniforms);
    device_.submit(commands);
    if (timestamps_) {
        const std::vector<double> ns = device_.readTimestamps(*timestamps_);
        stats.atlasPassMs = (ns[1] - ns[0]) * 1e-6;
        stats.litPassMs = (ns[2] - ns[1]) * 1e-6;
    }
    return stats;
}

} // namespace penumbra::render
