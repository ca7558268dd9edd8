#include "ContactShadowPass.hpp"

#include "DepthPrepass.hpp"

#include "penumbra/render/FrameResources.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <algorithm>
#include <fmt/format.h>
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

ContactShadowUniforms contactShadowUniforms(const rhi::Conventions& conventions, const scene::Camera& camera,
                                            const FrameDesc& frame, const LitFrameUniforms& lit)
{
    const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
    const glm::mat4 projection = conventions.perspective(camera.fovY, aspect, camera.nearPlane, camera.farPlane);
    const shadows::ContactShadowSettings& settings = frame.shadows.contact;
    ContactShadowUniforms u;
    u.worldToTexture = conventions.clipToTexture() * lit.viewProjection;
    // Inverted in double, as the screen-space collection's: the rebuilt positions lose no more than the depth's own
    // precision.
    u.clipToWorld = glm::mat4(glm::inverse(glm::dmat4(lit.viewProjection)));
    u.cameraPosition = lit.cameraPosition;
    u.cameraForward = lit.cameraForward;
    const int lights = std::min(lit.directionalLightCount, static_cast<int>(maxCollectedDirectionalLights));
    for (int i = 0; i < lights; ++i)
        u.towardsLight[i] = glm::vec4(-lit.lights[i].direction, 0.0f);
    u.targetSize = glm::vec4(static_cast<float>(frame.width), static_cast<float>(frame.height), 0.0f, 0.0f);
    u.depthToView = glm::vec4(projection[2][2], projection[3][2], camera.nearPlane, 0.0f);
    u.lightCount = lights;
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

void ContactShadowPass::prepare(std::uint32_t width, std::uint32_t height)
{
    width = contactShadowExtent(width);
    height = contactShadowExtent(height);
    if (shadows_ && shadows_->desc().width == width && shadows_->desc().height == height)
        return;
    shadows_ = device_.createTexture({.width = width,
                                      .height = height,
                                      .format = kContactShadowFormat,
                                      .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                      .debugName = "contact shadows"});
    const rhi::Attachment color{shadows_.get(), 0};
    target_ = device_.createFramebuffer({.colors = {&color, 1}, .debugName = "contact shadows"});
}

void ContactShadowPass::record(rhi::CommandList& commands, const rhi::Texture& depth, const rhi::UniformSlice& uniforms)
{
    commands.beginPass({.framebuffer = target_.get(), .clearColor = std::nullopt, .clearDepth = false});
    commands.bindPipeline(*pipeline_);
    rhi::bindUniform(commands, kContactBinding, uniforms);
    commands.bindTexture(kContactDepthBinding, depth, *sampler_);
    commands.draw(3);
    commands.endPass();
}

std::string ContactShadowsPass::name() const { return std::string(frame::kContactShadowsPass); }

bool ContactShadowsPass::setup(FramePassBuilder& builder)
{
    if (!state_.contact)
        return false;
    builder.read(frame::kLitDepth);
    builder.write(frame::kContactShadows);
    return true;
}

void ContactShadowsPass::execute(const FramePassContext& context)
{
    pass_->record(context.commands(), context.texture(frame::kLitDepth), state_.contactUniforms);
}

} // namespace penumbra::render
