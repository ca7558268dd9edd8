#include "ScreenSpaceShadowPass.hpp"

#include "DepthPrepass.hpp"

#include "penumbra/shaders/ShaderLibrary.hpp"
#include "penumbra/shadows/DirectionalShadowUniforms.hpp"
#include "penumbra/shadows/LocalShadowUniforms.hpp"
#include "penumbra/shadows/StaticShadowUniforms.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <glm/matrix.hpp>

namespace penumbra::render {
namespace {

// The parts of the lit shader the collection compiles: those of its directional shadows.
std::uint32_t shadowFeatureKey(const LitShaderFeatures& f)
{
    return (f.staticShadows ? 1u : 0u) | (f.tentFilters ? 2u : 0u) | (f.softFilters ? 4u : 0u);
}

rhi::ShaderSource collectionShader(const LitShaderFeatures& features)
{
    rhi::ShaderSource source = litShader("screen_space_shadows.frag", features);
    source.includes.push_back(
        {"screen_space_constants.glsl",
         shaders::uniformBlockGlsl(kCollectionBlock, kCollectionBinding, "collection") +
             fmt::format("#define PENUMBRA_BINDING_COLLECTION_DEPTH {}\n"
                         "#define PENUMBRA_BINDING_COLLECTION_POSITION_DX {}\n"
                         "#define PENUMBRA_BINDING_COLLECTION_POSITION_DY {}\n",
                         kCollectionDepthBinding, kCollectionPositionDxBinding, kCollectionPositionDyBinding)});
    return source;
}

std::unique_ptr<rhi::Texture> target(rhi::Device& device, const rhi::TextureDesc& like, rhi::Format format,
                                     const char* name)
{
    return device.createTexture({.width = like.width,
                                 .height = like.height,
                                 .format = format,
                                 .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                 .debugName = name});
}

} // namespace

ScreenSpaceShadowUniforms screenSpaceShadowUniforms(const LitFrameUniforms& frame, std::uint32_t width,
                                                    std::uint32_t height)
{
    ScreenSpaceShadowUniforms u;
    u.clipToWorld = glm::mat4(glm::inverse(glm::dmat4(frame.viewProjection)));
    u.cameraPosition = frame.cameraPosition;
    u.cameraForward = frame.cameraForward;
    const int lights = std::min(frame.directionalLightCount, static_cast<int>(maxCollectedDirectionalLights));
    std::copy_n(frame.lights.begin(), lights, u.lights.begin());
    u.targetSize = glm::vec4(static_cast<float>(width), static_cast<float>(height), 0.0f, 0.0f);
    u.lightCount = lights;
    return u;
}

ScreenSpaceShadowPass::ScreenSpaceShadowPass(rhi::Device& device, const rhi::BindingSetLayout& shadowMaps)
    : device_(device), shadowMaps_(shadowMaps), vertex_(device.createShader(shaders::load("fullscreen.vert"))),
      sampler_(device.createSampler({.magFilter = rhi::Filter::Nearest,
                                     .minFilter = rhi::Filter::Nearest,
                                     .debugName = "screen-space shadows (nearest)"}))
{
}

void ScreenSpaceShadowPass::prepare(const rhi::Texture& depth)
{
    depth_ = &depth;
    const rhi::TextureDesc& size = depth.desc();
    positionDx_ = target(device_, size, kReceiverDerivativeFormat, "receiver position dFdx");
    positionDy_ = target(device_, size, kReceiverDerivativeFormat, "receiver position dFdy");
    shadows_ = target(device_, size, kScreenSpaceShadowFormat, "screen-space shadows");
    const std::array<rhi::Attachment, 2> derivatives{{{positionDx_.get(), 0}, {positionDy_.get(), 0}}};
    receiverTarget_ = device_.createFramebuffer(
        {.colors = derivatives, .depth = {&depth, 0}, .debugName = "depth prepass (receivers)"});
    const rhi::Attachment shadows{shadows_.get(), 0};
    shadowTarget_ = device_.createFramebuffer({.colors = {&shadows, 1}, .debugName = "screen-space shadows"});
}

const rhi::Pipeline& ScreenSpaceShadowPass::pipeline(const LitShaderFeatures& features)
{
    const std::uint32_t key = shadowFeatureKey(features);
    std::unique_ptr<rhi::Pipeline>& pipeline = pipelines_[key];
    if (pipeline)
        return *pipeline;
    std::unique_ptr<rhi::Shader>& fragment = fragments_[key];
    fragment = device_.createShader(collectionShader(features));
    rhi::PipelineDesc desc;
    desc.vertex = vertex_.get();
    desc.fragment = fragment.get();
    desc.colorTargets = {rhi::ColorTarget{kScreenSpaceShadowFormat}};
    desc.bindingSetLayouts = {&shadowMaps_};
    desc.uniformLayouts = {shaders::uniformLayout(kCollectionBlock),
                           shaders::uniformLayout(shadows::kDirectionalShadowBlock)};
    // The static maps' functions come with local_shadows.glsl's block (screen_space_shadows.frag).
    if (features.staticShadows) {
        desc.uniformLayouts.insert(desc.uniformLayouts.end(), {shaders::uniformLayout(shadows::kLocalShadowBlock),
                                                               shaders::uniformLayout(shadows::kStaticShadowBlock)});
        desc.storageLayouts = {shaders::storageLayout(shadows::kLocalShadowTilesBlock)};
    }
    desc.debugName = fmt::format("screen-space shadows (features {:#x})", key);
    pipeline = device_.createPipeline(desc);
    return *pipeline;
}

void ScreenSpaceShadowPass::begin(rhi::CommandList& commands, const LitShaderFeatures& features,
                                  const rhi::UniformSlice& uniforms)
{
    commands.beginPass({.framebuffer = shadowTarget_.get(), .clearColor = std::nullopt, .clearDepth = false});
    commands.bindPipeline(pipeline(features));
    rhi::bindUniform(commands, kCollectionBinding, uniforms);
    commands.bindTexture(kCollectionDepthBinding, *depth_, *sampler_);
    commands.bindTexture(kCollectionPositionDxBinding, *positionDx_, *sampler_);
    commands.bindTexture(kCollectionPositionDyBinding, *positionDy_, *sampler_);
}

void ScreenSpaceShadowPass::draw(rhi::CommandList& commands) const
{
    commands.draw(3);
    commands.endPass();
}

} // namespace penumbra::render
