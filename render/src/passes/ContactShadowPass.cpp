#include "ContactShadowPass.hpp"

#include "penumbra/render/FrameResources.hpp"
#include "penumbra/scene/ViewFrustum.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"
#include "penumbra/shadows/ContactLights.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace penumbra::render {
namespace {

rhi::ShaderSource contactShader()
{
    rhi::ShaderSource source = litShader("contact_shadows.frag");
    source.includes.push_back({"contact_constants.glsl",
                               shaders::uniformBlockGlsl(kContactBlock, kContactBinding, "contact") +
                                   fmt::format("#define PENUMBRA_BINDING_CONTACT_DEPTH {}\n", kContactDepthBinding)});
    return source;
}

} // namespace

std::vector<std::uint32_t> contactLocalLights(const scene::Scene& scene, const scene::Camera& camera,
                                              const FrameDesc& frame, const shadows::LocalShadowPlan& plan,
                                              const shadows::StaticShadowPlan& staticPlan)
{
    const scene::ViewFrustum view(camera, static_cast<float>(frame.width) / static_cast<float>(frame.height));
    std::vector<shadows::ContactLightCandidate> candidates;
    const auto consider = [&](std::uint32_t light, int tile, glm::vec3 position, float range, float strength) {
        const bool staticMap = light < staticPlan.localLightMaps.size() && staticPlan.localLightMaps[light].tile >= 0;
        if ((tile >= 0 || staticMap) && strength > 0.0f &&
            view.mayShow({position - glm::vec3(range), position + glm::vec3(range)}))
            candidates.push_back({light, position, range});
    };
    const auto spots = static_cast<std::uint32_t>(scene.spotLights.size());
    for (std::uint32_t i = 0; i < spots; ++i) {
        const scene::SpotLight& l = scene.spotLights[i];
        consider(i, plan.spotTiles[i], l.position, l.range, l.shadowStrength);
    }
    for (std::uint32_t i = 0; i < scene.pointLights.size(); ++i) {
        const scene::PointLight& l = scene.pointLights[i];
        consider(spots + i, plan.pointShadows[i], l.position, l.range, l.shadowStrength);
    }
    return shadows::nearestContactLights(camera.position, candidates, frame.shadows.contact.localLights);
}

ContactShadowUniforms contactShadowUniforms(const rhi::Conventions& conventions, const scene::Camera& camera,
                                            const FrameDesc& frame, const LitFrameUniforms& lit,
                                            const scene::Scene& scene, std::span<const std::uint32_t> localLights)
{
    const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
    const glm::mat4 projection = conventions.perspective(camera.fovY, aspect, camera.nearPlane, camera.farPlane);
    const shadows::ContactShadowSettings& settings = frame.shadows.contact;
    ContactShadowUniforms u;
    u.worldToTexture = conventions.clipToTexture() * lit.viewProjection;
    u.cameraPosition = lit.cameraPosition;
    u.cameraForward = lit.cameraForward;
    // View x = x_ndc * viewDepth / projection[0][0], y likewise: the x and y rows of every convention's projection.
    const glm::mat4 viewToWorld = glm::inverse(camera.view());
    u.viewRayRight = glm::vec4(glm::vec3(viewToWorld[0]) / projection[0][0], 0.0f);
    u.viewRayUp = glm::vec4(glm::vec3(viewToWorld[1]) / projection[1][1], 0.0f);
    u.nearPlane = camera.nearPlane;
    const int lights = std::min(lit.directionalLightCount, static_cast<int>(maxCollectedDirectionalLights));
    for (int i = 0; i < lights; ++i)
        u.towardsLight[i] = glm::vec4(-lit.lights[i].direction, 0.0f);
    u.targetSize = glm::vec4(static_cast<float>(frame.width), static_cast<float>(frame.height), 0.0f, 0.0f);
    u.lightCount = lights;
    const auto spots = static_cast<std::uint32_t>(scene.spotLights.size());
    const std::size_t locals = std::min<std::size_t>(localLights.size(), shadows::kMaxContactLocalLights);
    for (std::size_t k = 0; k < locals; ++k) {
        const std::uint32_t i = localLights[k];
        if (i < spots) {
            const scene::SpotLight& l = scene.spotLights[i];
            u.localPosition[k] = glm::vec4(l.position, 1.0f / (l.range * l.range));
            u.localCone[k] = glm::vec4(glm::normalize(l.direction), std::cos(l.outerAngle));
        } else {
            const scene::PointLight& l = scene.pointLights[i - spots];
            u.localPosition[k] = glm::vec4(l.position, 1.0f / (l.range * l.range));
            u.localCone[k] = glm::vec4(0.0f, 0.0f, 0.0f, -2.0f);
        }
    }
    u.localLightCount = static_cast<std::int32_t>(locals);
    u.steps = static_cast<std::int32_t>(settings.steps);
    u.marchLength = settings.length;
    u.thickness = settings.thickness;
    return u;
}

ContactShadowPass::ContactShadowPass(rhi::Device& device)
    : device_(device), vertex_(device.createShader(shaders::load("fullscreen.vert"))),
      fragment_(device.createShader(contactShader())),
      sampler_(device.createSampler({.magFilter = rhi::Filter::Nearest,
                                     .minFilter = rhi::Filter::Nearest,
                                     .debugName = "contact shadows (nearest)"}))
{
    rhi::PipelineDesc desc;
    desc.vertex = vertex_.get();
    desc.fragment = fragment_.get();
    desc.colorTargets = {rhi::ColorTarget{kContactShadowFormat}};
    desc.uniformLayouts = {shaders::uniformLayout(kContactBlock)};
    desc.debugName = "contact shadows";
    pipeline_ = device.createPipeline(desc);
}

void ContactShadowPass::prepare(std::uint32_t width, std::uint32_t height, bool receivers)
{
    if (!prepass_)
        prepass_ = std::make_unique<DepthPrepass>(device_, kLitDepthFormat, 1, false, true);
    if (receivers && !receiverPrepass_)
        receiverPrepass_ = std::make_unique<DepthPrepass>(device_, kLitDepthFormat, 1, true, true);
    if (viewDepth_ && viewDepth_->desc().width == width && viewDepth_->desc().height == height)
        return;
    viewDepth_ = device_.createTexture({.width = width,
                                        .height = height,
                                        .format = kViewDepthFormat,
                                        .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                        .debugName = "contact view depth"});
    shadows_ = device_.createTexture({.width = contactShadowExtent(width),
                                      .height = contactShadowExtent(height),
                                      .format = kContactShadowFormat,
                                      .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                      .debugName = "contact shadows"});
    const rhi::Attachment color{shadows_.get(), 0};
    target_ = device_.createFramebuffer({.colors = {&color, 1}, .debugName = "contact shadows"});
}

void ContactShadowPass::record(rhi::CommandList& commands, const rhi::UniformSlice& uniforms)
{
    commands.beginPass({.framebuffer = target_.get(), .clearColor = std::nullopt, .clearDepth = false});
    commands.bindPipeline(*pipeline_);
    rhi::bindUniform(commands, kContactBinding, uniforms);
    commands.bindTexture(kContactDepthBinding, *viewDepth_, *sampler_);
    commands.draw(3);
    commands.endPass();
}

std::string ContactShadowsPass::name() const { return std::string(frame::kContactShadowsPass); }

bool ContactShadowsPass::setup(FramePassBuilder& builder)
{
    if (!state_.contact)
        return false;
    builder.read(frame::kContactViewDepth);
    builder.write(frame::kContactShadows);
    return true;
}

void ContactShadowsPass::execute(const FramePassContext& context)
{
    pass_->record(context.commands(), state_.contactUniforms);
}

} // namespace penumbra::render
