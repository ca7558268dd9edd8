#include "LitPasses.hpp"

#include "../EnvironmentMaps.hpp"
#include "../LocalLightTextures.hpp"
#include "ContactShadowPass.hpp"
#include "LitPipelines.hpp"
#include "ScreenSpaceShadowPass.hpp"

#include "penumbra/render/FrameResources.hpp"
#include "penumbra/render/GpuScene.hpp"

namespace penumbra::render {
namespace {

constexpr glm::vec4 kBackground{0.2f, 0.22f, 0.26f, 1.0f}; // sRGB-encoded, as the lit shader writes
constexpr glm::vec4 kUndecided{1.0f, 1.0f, 1.0f, 0.0f}; // the visibility view where no shadow map decides

// The frame's lit draws into `target`: after the depth prepass (features.depthPrepassed) the opaque objects are
// drawn with an equal depth test into the prepass's depth; otherwise the target's depth is cleared. Each draw takes
// `features` with its material's maps; `pixelDepth` is the single-sampled lit depth where a multisampled pass reads
// it (pixel_surface.glsl). Returns the draws issued.
std::uint32_t recordLitDraws(rhi::CommandList& commands, const rhi::Framebuffer& target, LitPipelines& pipelines,
                             const rhi::UniformSlice& frameSlice, const LitShaderFeatures& features,
                             const FrameState& state, const GpuScene& gpuScene, const ScreenSpaceShadowPass* collection,
                             const rhi::Texture* pixelDepth = nullptr)
{
    const scene::Scene& scene = gpuScene.scene();
    const bool visibility = features.view == LitView::Visibility;
    // The visibility view reports shadows on every surface: blended ones are drawn opaque there, so the alpha
    // channel keeps saying whether a shadow map decides the pixel.
    commands.beginPass({.framebuffer = &target,
                        .clearColor = visibility ? kUndecided : kBackground,
                        .clearDepth = !features.depthPrepassed});
    // A set stays bound across pipeline changes.
    commands.bindBindingSet(*state.shadowMapSet);
    const rhi::Pipeline* bound = nullptr;
    for (const LitDraw& draw : state.litDraws) {
        const scene::Object& object = scene.objects[draw.object];
        const scene::Material& material = scene.materialOf(object);
        const bool blend = material.blend && !visibility;
        LitShaderFeatures objectFeatures = features;
        objectFeatures.materialMaps = litMaterialMaps(material);
        const rhi::Pipeline* pipeline = &pipelines.choose(objectFeatures, material.doubleSided, blend);
        if (pipeline != bound) {
            // The frame's other bindings with each pipeline, as before; bindings survive a pipeline change, so the
            // shadow maps' set is bound once, above.
            commands.bindPipeline(*pipeline);
            rhi::bindUniform(commands, kLitFrameBinding, frameSlice);
            state.localLights->bind(commands);
            state.environment->bind(commands);
            if (features.directionalShadows != DirectionalShadowSource::Forward)
                commands.bindTexture(kLitScreenSpaceShadowsBinding, collection->shadows(), collection->sampler());
            // Only where the lit pass does not draw into it: multisampled, the single-sampled depth is no attachment.
            if (pixelDepth)
                commands.bindTexture(kLitScreenSpaceDepthBinding, *pixelDepth,
                                     collection ? collection->sampler() : state.contactShadows->sampler());
            if (features.contactShadows)
                commands.bindTexture(kLitContactShadowsBinding, state.contactShadows->shadows(),
                                     state.contactShadows->sampler());
            bound = pipeline;
        }
        rhi::bindUniform(commands, kLitObjectBinding, draw.uniforms);
        recordLitDraw(commands, gpuScene, draw);
    }
    commands.endPass();
    return static_cast<std::uint32_t>(state.litDraws.size());
}

} // namespace

std::string LitPass::name() const { return std::string(frame::kLitPass); }

LitShaderFeatures LitPass::features() const
{
    LitShaderFeatures features = state_.features;
    features.depthPrepassed = state_.desc->depthPrepass;
    features.contactShadows = state_.contact;
    if (state_.screenSpace)
        features.directionalShadows =
            state_.multisampled ? DirectionalShadowSource::ScreenSpaceEdges : DirectionalShadowSource::ScreenSpace;
    return features;
}

// Multisampled, the screen-space shadows' edge fallback and the contact shadows tell a fragment on its pixel's
// single-sampled surface by the lit depth.
bool LitPass::readsPixelDepth(const LitShaderFeatures& f) const
{
    return f.directionalShadows == DirectionalShadowSource::ScreenSpaceEdges ||
           (f.contactShadows && state_.multisampled);
}

bool LitPass::setup(FramePassBuilder& builder)
{
    const LitShaderFeatures f = features();
    readShadowMaps(builder);
    readLocalLights(builder);
    if (f.directionalShadows != DirectionalShadowSource::Forward)
        builder.read(frame::kScreenSpaceShadows);
    if (f.contactShadows)
        builder.read(frame::kContactShadows);
    if (readsPixelDepth(f))
        builder.read(frame::kLitDepth);
    const std::string_view depth = state_.multisampled ? frame::kMultisampledDepth : frame::kLitDepth;
    if (f.depthPrepassed)
        builder.read(depth, ResourceUse::AttachmentRead);
    else
        builder.write(depth);
    builder.write(state_.multisampled ? frame::kMultisampledColor : frame::kLitImage);
    readLitDraws(builder, state_);
    return true;
}

void LitPass::execute(const FramePassContext& context)
{
    const rhi::Framebuffer& target = state_.multisampled
                                         ? context.framebuffer({frame::kMultisampledColor}, frame::kMultisampledDepth)
                                         : context.framebuffer({frame::kLitImage}, frame::kLitDepth);
    const LitShaderFeatures f = features();
    state_.stats->litDraws =
        recordLitDraws(context.commands(), target, pipelines_, state_.litFrame, f, state_, scene_, collection_,
                       readsPixelDepth(f) ? &context.texture(frame::kLitDepth) : nullptr);
}

std::string ResolvePass::name() const { return std::string(frame::kResolvePass); }

bool ResolvePass::setup(FramePassBuilder& builder)
{
    if (!state_.multisampled)
        return false;
    builder.read(frame::kMultisampledColor, ResourceUse::TransferSource);
    builder.write(frame::kLitImage, ResourceUse::TransferDestination);
    return true;
}

void ResolvePass::execute(const FramePassContext& context)
{
    context.commands().resolveTexture(context.texture(frame::kMultisampledColor), litImage_);
}

std::string LitViewPass::name() const
{
    return std::string(view_ == LitView::Cascades ? frame::kCascadeViewPass : frame::kVisibilityViewPass);
}

bool LitViewPass::setup(FramePassBuilder& builder)
{
    readShadowMaps(builder);
    readLocalLights(builder);
    if (view_ == LitView::Visibility && state_.contact)
        builder.read(frame::kContactShadows);
    builder.write(frame::kLitDepth);
    builder.write(view_ == LitView::Cascades ? frame::kCascadeView : frame::kVisibilityView);
    readLitDraws(builder, state_);
    return true;
}

void LitViewPass::execute(const FramePassContext& context)
{
    const bool cascades = view_ == LitView::Cascades;
    const rhi::Framebuffer& target =
        context.framebuffer({cascades ? frame::kCascadeView : frame::kVisibilityView}, frame::kLitDepth);
    // The cascade view keeps the lit pass's shader parts; the visibility view of any light takes every part of the
    // shader: a debug view, not worth a variant each.
    LitShaderFeatures features{.view = LitView::Visibility, .contactShadows = state_.contact};
    if (cascades) {
        features = state_.features;
        features.view = LitView::Cascades;
    }
    // The lit view's block, but for the view it draws.
    LitFrameUniforms frameBlock = state_.litFrameUniforms;
    frameBlock.litView = static_cast<int>(view_);
    if (!cascades)
        frameBlock.visibilityLight = state_.visibilityLight;
    const rhi::UniformSlice frameSlice = state_.uniforms->push(frameBlock);
    recordLitDraws(context.commands(), target, pipelines_, frameSlice, features, state_, scene_, nullptr);
}

} // namespace penumbra::render
