#include "FrameTargets.hpp"

#include "FrameChecks.hpp"
#include "LocalLightTextures.hpp"
#include "cache/LocalTileCache.hpp"
#include "graph/ApplicationPasses.hpp"
#include "graph/FrameGraph.hpp"
#include "passes/ContactShadowPass.hpp"
#include "passes/DepthPrepass.hpp"
#include "passes/DepthReduction.hpp"
#include "passes/FrameState.hpp"
#include "passes/LitPipelines.hpp"
#include "passes/ScreenSpaceShadowPass.hpp"
#include "skinning/GpuSkinning.hpp"
#include "static/StaticShadowCache.hpp"

#include "penumbra/render/FrameResources.hpp"

namespace penumbra::render {
namespace {

constexpr std::uint32_t kStandInAtlasSize = 16; // an atlas without tiles in use

std::unique_ptr<rhi::Texture> colorTarget(rhi::Device& device, const FrameDesc& frame, const std::string& name)
{
    return device.createTexture({.width = frame.width,
                                 .height = frame.height,
                                 .format = kLitColorFormat,
                                 .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                 .debugName = name});
}

} // namespace

rhi::TextureDesc depthTargetDesc(const FrameDesc& frame, std::uint32_t samples)
{
    return {.width = frame.width,
            .height = frame.height,
            .format = kLitDepthFormat,
            .usage = samples == 1 ? rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget
                                  : rhi::TextureUsage::RenderTarget,
            .samples = samples};
}

void createMultisampledTargets(FrameGraph& graph, const FrameDesc& frame)
{
    graph.createTexture(frame::kMultisampledColor, {.width = frame.width,
                                                    .height = frame.height,
                                                    .format = kLitColorFormat,
                                                    .usage = rhi::TextureUsage::RenderTarget,
                                                    .samples = frame.msaa});
    graph.createTexture(frame::kMultisampledDepth, depthTargetDesc(frame, frame.msaa));
}

void prepareContactShadows(rhi::Device& device, const FrameDesc& frame, std::unique_ptr<ContactShadowPass>& contact)
{
    if (!contact)
        contact = std::make_unique<ContactShadowPass>(device);
    contact->prepare(frame.width, frame.height, frame.shadowPath == ShadowPath::ScreenSpace);
}

void SceneRenderer::prepareTargets(const FrameDesc& frame, const ShadowPlans& plans)
{
    checkFrameSize(frame);
    // An atlas without a tile in use is a small stand-in: the lit pass reads no texel of it, and a full-size one
    // would still be cleared every frame (what Catlike Coding's "Directional Shadows" tutorial, section "Shadow
    // Atlas", avoids with its 1 x 1 dummy texture).
    const shadows::DirectionalShadowSettings& directional = frame.shadows.directional;
    const std::uint32_t atlasSize = plans.directional.lights.empty() ? kStandInAtlasSize : directional.atlasSize;
    if (!atlas_ || atlas_->size() != atlasSize || atlas_->format() != directional.atlasFormat)
        atlas_ = std::make_unique<shadows::ShadowAtlas>(device_, atlasSize, directional.atlasFormat,
                                                        "directional shadow atlas");
    const shadows::LocalShadowSettings& local = frame.shadows.local;
    const std::uint32_t localSize = plans.local.tiles.empty() ? kStandInAtlasSize : local.atlasSize;
    if (!localAtlas_ || localAtlas_->size() != localSize || localAtlas_->format() != local.atlasFormat) {
        localAtlas_ =
            std::make_unique<shadows::ShadowAtlas>(device_, localSize, local.atlasFormat, "local shadow atlas");
        localTiles_->invalidate();
    }
    // Cube-map mode keeps room for every cube it may plan; otherwise one small cube stands in for the binding.
    const bool cubeMode = local.pointMode == shadows::PointShadowMode::CubeMap;
    const std::uint32_t faceSize = cubeMode ? local.cubeMapSize : 16;
    const std::uint32_t cubeCount = cubeMode ? shadows::maxShadowCubes : 1;
    if (!shadowCubes_ || shadowCubes_->faceSize() != faceSize || shadowCubes_->cubeCount() != cubeCount ||
        shadowCubes_->format() != local.atlasFormat)
        shadowCubes_ = std::make_unique<shadows::ShadowCubes>(device_, faceSize, cubeCount, local.atlasFormat);
    if (frame.msaa > 1 && (!multisampledLitPipelines_ || multisampledLitPipelines_->samples() != frame.msaa))
        multisampledLitPipelines_ = std::make_unique<LitPipelines>(device_, *litVertex_, *shadowMapLayout_, frame.msaa);
    if (depthPrepass_->samples() != frame.msaa)
        depthPrepass_ = std::make_unique<DepthPrepass>(device_, kLitDepthFormat, frame.msaa);
    const bool depthFit = frame.shadows.directional.projection == shadows::CascadeProjection::DepthFit;
    const bool contact = frame.shadows.contact.shadows == shadows::Toggle::On;
    if (depthFit && !depthReduction_)
        depthReduction_ = std::make_unique<DepthReduction>(device_);
    if (contact)
        prepareContactShadows(device_, frame, contact_);
    // With contact shadows, theirs (ContactShadowPass::prepass), which writes the view depth too.
    if (depthFit && !contact && frame.msaa > 1 && !singleSampledPrepass_)
        singleSampledPrepass_ = std::make_unique<DepthPrepass>(device_, kLitDepthFormat, 1);
    const bool firstScreenSpace = frame.shadowPath == ShadowPath::ScreenSpace && !screenSpace_;
    if (firstScreenSpace) {
        receiverPrepass_ = std::make_unique<DepthPrepass>(device_, kLitDepthFormat, 1, true);
        screenSpace_ = std::make_unique<ScreenSpaceShadowPass>(device_, *shadowMapLayout_);
    }
    if (lit_ && lit_->desc().width == frame.width && lit_->desc().height == frame.height) {
        if (firstScreenSpace)
            screenSpace_->prepare(*depth_);
        return;
    }
    lit_ = colorTarget(device_, frame, "lit image");
    cascades_ = colorTarget(device_, frame, "cascade view");
    visibility_ = colorTarget(device_, frame, "visibility view");
    rhi::TextureDesc depth = depthTargetDesc(frame, 1);
    depth.debugName = "lit depth";
    depth_ = device_.createTexture(depth);
    graph_->dropFramebuffers();
    if (screenSpace_)
        screenSpace_->prepare(*depth_);
}

// This frame's textures and buffers: the renderer's, the frame's transient ones and the application's.
void SceneRenderer::importResources(const FrameDesc& frame)
{
    FrameGraph& graph = *graph_;
    graph.reset();
    const FrameState& state = *state_;
    graph.importTexture(frame::kLitImage, *lit_, true);
    graph.importTexture(frame::kLitDepth, *depth_);
    graph.importTexture(frame::kDirectionalAtlas, atlas_->texture(), true);
    graph.importTexture(frame::kLocalAtlas, localAtlas_->texture(), true);
    graph.importTexture(frame::kShadowCubes, shadowCubes_->texture(), true);
    graph.importTexture(frame::kStaticDirectionalAtlas, staticShadows_->directionalAtlas().texture(), true);
    graph.importTexture(frame::kStaticLocalAtlas, staticShadows_->localAtlas().texture(), true);
    graph.importTexture(frame::kLocalLights, localLights_->lights());
    graph.importTexture(frame::kLightClusters, localLights_->clusters());
    graph.importTexture(frame::kLightIndices, localLights_->indices());
    graph.importTexture(frame::kCascadeView, *cascades_, frame.cascadeView);
    graph.importTexture(frame::kVisibilityView, *visibility_, frame.visibilityOf.has_value());
    if (screenSpace_) {
        graph.importTexture(frame::kReceiverPositionDx, screenSpace_->positionDx());
        graph.importTexture(frame::kReceiverPositionDy, screenSpace_->positionDy());
        graph.importTexture(frame::kScreenSpaceShadows, screenSpace_->shadows(), state.screenSpace);
    }
    if (contact_) {
        graph.importTexture(frame::kContactShadows, contact_->shadows());
        graph.importTexture(frame::kContactViewDepth, contact_->viewDepth());
    }
    if (frame.msaa > 1)
        createMultisampledTargets(graph, frame);
    applicationPasses_->importResources(graph);
    if (state.posedVertices)
        graph.importBuffers(frame::kPosedVertices, skinning_->posedVertices());
    const auto importCulled = [&](const shadows::GpuCasterCulling* culling, const CulledBuffers& buffers) {
        if (!culling)
            return;
        graph.importBuffer(buffers.instances, culling->instances());
        graph.importBuffers(buffers.draws, {&culling->draws(), &culling->drawCounts()});
    };
    importCulled(state.culling, kCulledCasters);
    importCulled(state.viewCulling, kViewCulled);
    if (state.depthFit)
        graph.importBuffer(frame::kDepthHistogram, depthReduction_->histogram(), true);
}

} // namespace penumbra::render
