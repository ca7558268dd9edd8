#include "penumbra/render/SceneRenderer.hpp"

#include "FrameChecks.hpp"
#include "FrameNotes.hpp"
#include "FrameTargets.hpp"
#include "EnvironmentMaps.hpp"
#include "LocalLightTextures.hpp"
#include "ShadowInputs.hpp"
#include "TextureSampling.hpp"
#include "cache/LocalTileCache.hpp"
#include "graph/ApplicationPasses.hpp"
#include "graph/FrameGraph.hpp"
#include "passes/ContactShadowPass.hpp"
#include "passes/FrameState.hpp"
#include "passes/CullingPasses.hpp"
#include "passes/LightClusterPass.hpp"
#include "passes/DepthFitPasses.hpp"
#include "passes/DepthPrepass.hpp"
#include "passes/DepthReduction.hpp"
#include "passes/LitDraws.hpp"
#include "passes/GpuViewCulling.hpp"
#include "passes/LitPasses.hpp"
#include "passes/LitPipelines.hpp"
#include "passes/PrepassPasses.hpp"
#include "passes/ScreenSpaceShadowPass.hpp"
#include "passes/ShadowMapPasses.hpp"
#include "skinning/GpuSkinning.hpp"
#include "skinning/SkinningPass.hpp"
#include "static/StaticMapHashes.hpp"
#include "static/StaticShadowCache.hpp"
#include "static/StaticTileCache.hpp"

#include "penumbra/render/FrameResources.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"
#include "penumbra/shadows/DirectionalShadowUniforms.hpp"
#include "penumbra/shadows/LocalShadowUniforms.hpp"
#include "penumbra/shadows/ShadowCaster.hpp"
#include "penumbra/shadows/StaticShadowUniforms.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/trigonometric.hpp>
#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace penumbra::render {
namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

float aspectOf(const FrameDesc& frame) { return static_cast<float>(frame.width) / static_cast<float>(frame.height); }

} // namespace

SceneRenderer::SceneRenderer(rhi::Device& device, const scene::Scene& scene)
    : device_(device), gpuScene_(device, scene), skinning_(std::make_unique<GpuSkinning>(device, gpuScene_)),
      shadowPass_(device, GpuScene::vertexFormat()), localShadowPass_(device, GpuScene::vertexFormat()),
      localTiles_(std::make_unique<LocalTileCache>(device, GpuScene::vertexFormat())),
      litVertex_(device.createShader(litShader("lit.vert"))),
      shadowMapLayout_(device.createBindingSetLayout(ShadowMapBindings::layoutDesc())),
      litPipelines_(std::make_unique<LitPipelines>(device, *litVertex_, *shadowMapLayout_, 1)),
      depthPrepass_(std::make_unique<DepthPrepass>(device, kLitDepthFormat, 1)),
      staticShadows_(std::make_unique<StaticShadowCache>(device, GpuScene::vertexFormat())),
      environment_(std::make_unique<EnvironmentMaps>(device)),
      localLights_(std::make_unique<LocalLightTextures>(device)),
      directionalStaticTiles_(
          std::make_unique<StaticTileCache>(device, GpuScene::vertexFormat(), "directional atlas, static casters")),
      localStaticTiles_(
          std::make_unique<StaticTileCache>(device, GpuScene::vertexFormat(), "local atlas, static casters")),
      commands_(device.createCommandList()), graph_(std::make_unique<FrameGraph>(device)),
      state_(std::make_unique<FrameState>()), applicationPasses_(std::make_unique<ApplicationPasses>()),
      uniforms_(device, "lit pass uniforms"), instances_(device, "lit pass instances"),
      storage_(device, "lit pass storage", rhi::BufferUsage::Storage,
               std::max<std::uint64_t>(device.capabilities().storageBufferOffsetAlignment, 16))
{
}

SceneRenderer::~SceneRenderer() = default;

const rhi::Texture& SceneRenderer::screenSpaceShadowImage() const
{
    if (!screenSpace_)
        throw rhi::Error("screenSpaceShadowImage: no frame has been drawn with ShadowPath::ScreenSpace");
    return screenSpace_->shadows();
}

const shadows::ShadowAtlas& SceneRenderer::staticDirectionalAtlas() const { return staticShadows_->directionalAtlas(); }

const shadows::ShadowAtlas& SceneRenderer::staticLocalAtlas() const { return staticShadows_->localAtlas(); }

const shadows::StaticShadowPlan& SceneRenderer::staticPlan() const { return staticShadows_->plan(); }

void SceneRenderer::useBakedShadows(shadows::StaticShadowBake bake) { staticShadows_->useBake(std::move(bake)); }

shadows::StaticShadowBake SceneRenderer::bakeStaticShadows(const std::string& configuration) const
{
    const scene::Scene& scene = gpuScene_.scene();
    const shadows::StaticShadowPlan& plan = staticShadows_->plan();
    shadows::StaticShadowBake bake{configuration, {}, {}};
    for (const scene::Object& object : scene.objects)
        if (object.mobility == scene::Mobility::Static && scene.castsShadows(object))
            bake.objects.push_back(object.name);
    const std::vector<std::uint64_t> hashes = staticMapHashes(scene, plan);
    std::optional<rhi::DepthImage> directional, local;
    for (std::size_t i = 0; i < plan.maps.size(); ++i) {
        const shadows::StaticShadowMap& map = plan.maps[i];
        const bool isDirectional = map.kind == shadows::LightKind::Directional;
        std::optional<rhi::DepthImage>& depth = isDirectional ? directional : local;
        if (!depth)
            depth = rhi::readDepth(device_, (isDirectional ? staticDirectionalAtlas() : staticLocalAtlas()).texture());
        shadows::BakedShadowMap baked =
            shadows::bakeShadowMap(map, isDirectional ? plan.directionalAtlas : plan.localAtlas, *depth,
                                   device_.conventions());
        baked.lightName = lightName(scene, map.kind, map.lightIndex);
        baked.hash = hashes[i];
        bake.maps.push_back(std::move(baked));
    }
    return bake;
}

LitFrameUniforms SceneRenderer::frameUniforms(const scene::Camera& camera, const FrameDesc& frame,
                                              const shadows::LightClusterUniforms& clusters) const
{
    const float aspect = aspectOf(frame);
    const rhi::Conventions& conventions = device_.conventions();
    LitFrameUniforms u;
    u.viewProjection = conventions.perspective(camera.fovY, aspect, camera.nearPlane, camera.farPlane) * camera.view();
    u.cameraPosition = glm::vec4(camera.position, 1.0f);
    u.cameraForward = glm::vec4(camera.forward, 0.0f);
    const std::vector<scene::DirectionalLight>& lights = gpuScene_.scene().lights;
    const auto count = static_cast<std::uint32_t>(std::min<std::size_t>(lights.size(), maxLitDirectionalLights));
    for (std::uint32_t i = 0; i < count; ++i) {
        u.lights[i] = {.color = lights[i].color * lights[i].intensity,
                       .shadowSlot = plan_.shadowSlots[i],
                       .direction = glm::normalize(lights[i].direction)};
    }
    u.ambient = glm::vec4(frame.ambient.sky(), 0.0f);
    u.ambientGround = glm::vec4(frame.ambient.below(), 0.0f);
    if (environment_->present()) {
        const float turn = glm::radians(frame.environment.rotationDegrees);
        u.environmentCos = std::cos(turn);
        u.environmentSin = std::sin(turn);
        u.environmentLastLevel = float(kEnvironmentLevels - 1);
        u.environmentIntensity = frame.environment.intensity;
        for (std::size_t i = 0; i < u.environmentSh.size(); ++i)
            u.environmentSh[i] = glm::vec4(environment_->diffuse()[i], 0.0f);
    }
    u.directionalLightCount = static_cast<int>(count);
    u.litView = static_cast<int>(LitView::Lit);
    const scene::Scene& scene = gpuScene_.scene();
    u.localLightCount = static_cast<int>(scene.spotLights.size() + scene.pointLights.size());
    setClusterView(u, shadowCamera(camera, aspect), clusters);
    return u;
}

// The lit pass's order: directional lights, then spot lights, then point lights (localLightRecords).
int SceneRenderer::litLightIndex(const scene::LightRef& light) const
{
    const scene::Scene& scene = gpuScene_.scene();
    const char* kind = scene::lightKindName(light.kind);
    const std::size_t counts[] = {scene.lights.size(), scene.spotLights.size(), scene.pointLights.size()};
    const std::size_t count = counts[static_cast<std::size_t>(light.kind)];
    if (light.index >= count)
        throw rhi::Error(
            fmt::format("visibility view: {} {} does not exist (the scene has {})", kind, light.index, count));
    const std::size_t directional = std::min<std::size_t>(scene.lights.size(), maxLitDirectionalLights);
    if (light.kind == scene::LightKind::Directional) {
        if (light.index >= maxLitDirectionalLights)
            throw rhi::Error(fmt::format("visibility view: directional light {} is not drawn (at most {})", light.index,
                                         maxLitDirectionalLights));
        return static_cast<int>(light.index);
    }
    const std::size_t local = light.index + (light.kind == scene::LightKind::Point ? scene.spotLights.size() : 0);
    return static_cast<int>(directional + local);
}

GpuScene::CasterOptions SceneRenderer::casterOptions(const FrameDesc& frame) const
{
    GpuScene::CasterOptions options{.instancedDraws = frame.instancedDraws, .vertices = {}};
    if (!casterSkinning_)
        for (std::uint32_t mesh = 0; mesh < gpuScene_.scene().meshes.size(); ++mesh)
            options.vertices.push_back(skinning_->restVertices(mesh));
    return options;
}

ShadowPlans SceneRenderer::planShadows(const scene::Camera& camera, const FrameDesc& frame) const
{
    gpuScene_.refresh(casterOptions(frame));
    return planRefreshed(camera, frame);
}

ShadowPlans SceneRenderer::planRefreshed(const scene::Camera& camera, const FrameDesc& frame) const
{
    checkFrameSize(frame);
    const float aspect = aspectOf(frame);
    const scene::Scene& scene = gpuScene_.scene();
    const std::vector<shadows::Bounds>& bounds = gpuScene_.casterBounds();
    const std::vector<shadows::DirectionalShadowLightInput> lights = shadowLights(scene.lights);
    const std::vector<shadows::SpotShadowInput> spots = spotShadowInputs(scene.spotLights);
    const std::vector<shadows::PointShadowInput> points = pointShadowInputs(scene.pointLights);
    const std::vector<std::uint32_t>& staticCasters = gpuScene_.staticCasters();
    return {shadows::planDirectionalShadows(frame.shadows, device_.conventions(), shadowCamera(camera, aspect), lights,
                                            bounds,
                                            {depthHistogram_ ? &*depthHistogram_ : nullptr,
                                             plan_.depthFit ? &*plan_.depthFit : nullptr},
                                            {&lightSpace_, &gpuScene_.casterChanges()}),
            shadows::planLocalShadows(frame.shadows, device_.conventions(), shadowCamera(camera, aspect), spots, points,
                                      bounds, localPlan_.allocation),
            shadows::planStaticShadows(frame.shadows, device_.conventions(), lights, spots, points,
                                       {bounds, staticCasters})};
}

FrameStats SceneRenderer::render(const scene::Camera& camera, const FrameDesc& frame)
{
    const auto start = std::chrono::steady_clock::now();
    gpuScene_.refresh(casterOptions(frame));
    ShadowPlans plans = planRefreshed(camera, frame);
    const double planningMs = millisecondsSince(start);
    FrameStats stats = renderRefreshed(camera, frame, std::move(plans));
    stats.planningMs = planningMs;
    return stats;
}

// The frame's CPU half after planning: notes, the static maps to draw, the draws, casters and blocks that the passes
// read (state_).
FrameStats SceneRenderer::prepareFrame(const scene::Camera& camera, const FrameDesc& frame, ShadowPlans& plans)
{
    const scene::Scene& scene = gpuScene_.scene();
    notes_ = frameNotes(scene, plans);
    FrameStats stats = plannedFrameStats(scene, plans);
    const AnisotropyChoice anisotropy = chooseAnisotropy(frame.maxAnisotropy, device_.capabilities());
    gpuScene_.setMaxAnisotropy(anisotropy.value);
    if (anisotropy.note && !scene.textures.empty())
        notes_.push_back(*anisotropy.note);
    // Every static map mode, the settings' or a light's own, keeps static depth for the realtime tiles.
    const bool keepsStaticMaps = shadows::hasStaticMaps(frame.shadows) || !plans.staticMaps.maps.empty();
    if (staticShadows_->baked()) {
        if (!keepsStaticMaps)
            throw rhi::Error("baked shadows: the frame's settings keep no static maps (static.update is everyFrame, "
                             "and so is every light's own mode); set it to onChange or onDemand");
        staticShadows_->checkBake(plans.staticMaps, staticMapHashes(scene, plans.staticMaps));
    }
    FrameState& state = *state_;
    state = FrameState{.desc = &frame, .multisampled = frame.msaa > 1, .uniforms = &uniforms_};
    if (keepsStaticMaps && frame.shadows.staticMaps.realtimeCasters == shadows::RealtimeCasters::Dynamic)
        state.staticTiles = splitStaticCasters(plans, gpuScene_.staticCasters());
    plan_ = std::move(plans.directional);
    localPlan_ = std::move(plans.local);
    if (shadows::culledOnGpu(frame.shadows)) {
        if (!casterCulling_)
            casterCulling_ = std::make_unique<shadows::GpuCasterCulling>(device_);
        state.culling = casterCulling_.get();
        for (const shadows::ShadowedDirectionalLight& light : plan_.lights)
            state.culledLocalTile += static_cast<std::uint32_t>(light.cascades.size());
    }

    uniforms_.reset();
    instances_.reset();
    storage_.reset();
    litDraws_ = frameLitDraws(camera, frame, state.culling != nullptr);
    if (state.culling)
        prepareCasterCulling(*state.culling, gpuScene_.casters(), gpuScene_, plan_, localPlan_);
    state.posedVertices = !skinning_->empty();
    stats.staticMapUpdates = prepareStaticMaps(frame, std::move(plans.staticMaps));
    const shadows::StaticShadowUniforms& staticUniforms = staticShadows_->plan().uniforms;
    const std::optional<std::string> uncollected =
        frame.shadowPath == ShadowPath::ScreenSpace ? uncollectedShadows(scene, plan_, staticUniforms) : std::nullopt;
    if (uncollected)
        notes_.push_back(*uncollected);
    stats.notes = notes_;
    state.screenSpace = frame.shadowPath == ShadowPath::ScreenSpace && !uncollected;
    state.depthFit = frame.shadows.directional.projection == shadows::CascadeProjection::DepthFit;
    state.contact = frame.shadows.contact.shadows == shadows::Toggle::On;
    state.contactShadows = contact_.get();
    if (state.depthFit) {
        for (const shadows::ShadowedDirectionalLight& light : plan_.lights)
            state.depthFitLights.push_back(light.direction);
        state.depthFitShadowFar = std::max(std::min(frame.shadows.maxDistance, camera.farPlane), camera.nearPlane);
    }
    state.casters = gpuScene_.casters();
    state.litDraws = litDraws_;
    fillFrameBlocks(camera, frame);
    return stats;
}

// With GPU culling (and instancing) the opaque lit objects are culled against the view on the GPU too: nothing per
// object in a frame where nothing moved.
std::vector<LitDraw> SceneRenderer::frameLitDraws(const scene::Camera& camera, const FrameDesc& frame, bool culledOnGpu)
{
    const bool viewCulled = culledOnGpu && frame.instancedDraws;
    if (viewCulled) {
        if (!viewCulling_)
            viewCulling_ = std::make_unique<GpuViewCulling>(device_);
        viewCulling_->prepare(gpuScene_, camera, aspectOf(frame));
        state_->viewCulling = &viewCulling_->culling();
    }
    return litDraws(gpuScene_, camera.position, scene::ViewFrustum(camera, aspectOf(frame)), frame.instancedDraws,
                    uniforms_, instances_, viewCulled ? viewCulling_.get() : nullptr);
}

// The blocks the frame's passes bind (FrameState): the shadow maps', the lit view's and the debug views'.
void SceneRenderer::fillFrameBlocks(const scene::Camera& camera, const FrameDesc& frame)
{
    FrameState& state = *state_;
    const shadows::StaticShadowUniforms& staticUniforms = staticShadows_->plan().uniforms;
    state.shadowMaps = {atlas_.get(),
                        localAtlas_.get(),
                        shadowCubes_.get(),
                        staticShadows_.get(),
                        uniforms_.push(plan_.uniforms),
                        uniforms_.push(localPlan_.uniforms),
                        uniforms_.push(staticUniforms),
                        localTileSlice()};
    shadowMapSet_ = state.shadowMaps.createSet(device_, *shadowMapLayout_);
    state.shadowMapSet = shadowMapSet_.get();
    // Every spot and point light, listed in the clusters of the camera's view it may reach (here or on the GPU).
    const std::vector<std::uint32_t> contactLights =
        state.contact ? contactLocalLights(gpuScene_.scene(), camera, frame, localPlan_, staticShadows_->plan())
                      : std::vector<std::uint32_t>{};
    localLights_->updateLights(localLightRecords(gpuScene_.scene(), localPlan_, staticShadows_->plan(), contactLights));
    const shadows::LightClusterUniforms clusters =
        localLights_->prepareLists(shadowCamera(camera, aspectOf(frame)), clusterLights(gpuScene_.scene()),
                                   frame.shadows.local.clusterBuild);
    state.localLights = localLights_.get();
    state.gpuClusters = localLights_->gpuLists() ? localLights_.get() : nullptr;
    state.environment = environment_.get();
    state.litFrameUniforms = frameUniforms(camera, frame, clusters);
    state.litFrame = uniforms_.push(state.litFrameUniforms);
    if (state.contact) {
        const ContactShadowUniforms contact =
            contactShadowUniforms(device_.conventions(), camera, frame, state.litFrameUniforms, gpuScene_.scene(),
                                  contactLights);
        // No light to march towards: the frame skips the pass (a full-screen pass costs a software rasterizer a
        // fixed part before it marches at all, docs/notes/2026-12-07-contact-parity-cost.md), the view depth and the
        // lit pass's upsampling, whose answer would be lit everywhere.
        state.contact = contact.lightCount > 0 || contact.localLightCount > 0;
        if (state.contact)
            state.contactUniforms = uniforms_.push(contact);
    }
    if (frame.visibilityOf)
        state.visibilityLight = litLightIndex(*frame.visibilityOf);
    state.features = frameShaderFeatures(state.litFrameUniforms, plan_.uniforms, localPlan_, staticShadows_->plan());
}

// The local atlas's tiles in the storage arena; one empty tile stands in where the frame has none, since a storage
// binding takes at least one element.
rhi::BufferSlice SceneRenderer::localTileSlice()
{
    const std::vector<shadows::LocalAtlasTileData>& tiles = localPlan_.tileData;
    if (tiles.empty())
        return storage_.push(shadows::LocalAtlasTileData{});
    return storage_.push(std::as_bytes(std::span(tiles)));
}

// The static maps to draw this frame (StaticShadowCache::prepare), named with why.
std::vector<std::string> SceneRenderer::prepareStaticMaps(const FrameDesc& frame, shadows::StaticShadowPlan plan)
{
    const StaticMapDraws draws =
        staticShadows_->prepare(frame.shadows, std::move(plan), gpuScene_.casters(), staticUpdateRequested_);
    staticUpdateRequested_ = false;
    std::vector<std::string> updates;
    for (const StaticMapUpdate& update : draws.updates)
        updates.push_back(fmt::format("{} {} ('{}'): {}", scene::lightKindName(update.kind), update.lightIndex,
                                      lightName(gpuScene_.scene(), update.kind, update.lightIndex), update.reason));
    return updates;
}

// This frame's passes: the built-in ones in running order, each application pass beside the one it names.
void SceneRenderer::buildGraph(const FrameDesc& frame)
{
    FrameGraph& graph = *graph_;
    importResources(frame);
    const FrameState& state = *state_;
    LitPipelines& litPipelines = frame.msaa > 1 ? *multisampledLitPipelines_ : *litPipelines_;
    framePasses_.clear();
    const auto add = [&](std::unique_ptr<FramePass> pass) { framePasses_.push_back(std::move(pass)); };
    add(std::make_unique<SkinningPass>(*skinning_));
    add(std::make_unique<StaticMapsPass>(state, *staticShadows_));
    add(std::make_unique<CullingPass>(state, CullingPass::Kind::Casters));
    add(std::make_unique<CullingPass>(state, CullingPass::Kind::View));
    add(std::make_unique<LightClusterPass>(state));
    add(std::make_unique<StaticTilesPass>(state, *directionalStaticTiles_, StaticTilesPass::Atlas::Directional));
    add(std::make_unique<DirectionalAtlasPass>(state, shadowPass_, plan_));
    add(std::make_unique<StaticTilesPass>(state, *localStaticTiles_, StaticTilesPass::Atlas::Local));
    add(std::make_unique<LocalAtlasPass>(state, localShadowPass_, *localTiles_, localPlan_, gpuScene_.scene()));
    add(std::make_unique<DepthPrepassPass>(state, *depthPrepass_, gpuScene_));
    add(std::make_unique<SingleSampledDepthPass>(state, singleSampledPrepass_.get(), gpuScene_));
    if (screenSpace_) {
        add(std::make_unique<ReceiverPrepassPass>(state, *receiverPrepass_, *screenSpace_, gpuScene_));
        add(std::make_unique<ScreenSpaceShadowsPass>(state, *screenSpace_));
    }
    add(std::make_unique<ContactShadowsPass>(state, contact_.get()));
    add(std::make_unique<LitPass>(state, litPipelines, gpuScene_, screenSpace_.get()));
    add(std::make_unique<DepthReductionPass>(state, depthReduction_.get()));
    add(std::make_unique<ResolvePass>(state, *lit_));
    add(std::make_unique<LitViewPass>(state, *litPipelines_, gpuScene_, LitView::Cascades));
    add(std::make_unique<LitViewPass>(state, *litPipelines_, gpuScene_, LitView::Visibility));
    for (const std::unique_ptr<FramePass>& pass : framePasses_)
        applicationPasses_->addAround(graph, *pass);
}

// Depth fit: this frame's histogram, read after the submission (which waited for it), is the next frame's.
void SceneRenderer::readDepthHistogram()
{
    if (!state_->depthFit)
        return;
    if (std::optional<shadows::DepthHistogram> histogram = depthReduction_->read())
        depthHistogram_ = std::move(*histogram);
}

std::optional<shadows::ViewDepthRange> SceneRenderer::visibleDepths() const
{
    return depthHistogram_ ? shadows::depthHistogramRange(*depthHistogram_) : std::nullopt;
}

void SceneRenderer::addPass(std::shared_ptr<FramePass> pass, PassPlacement placement)
{
    applicationPasses_->addPass(std::move(pass), std::move(placement));
}

void SceneRenderer::addTexture(std::string name, const rhi::Texture& texture)
{
    applicationPasses_->addTexture(std::move(name), texture);
}

void SceneRenderer::addBuffer(std::string name, const rhi::Buffer& buffer)
{
    applicationPasses_->addBuffer(std::move(name), buffer);
}

std::string SceneRenderer::frameGraphDot() const { return graph_->dot(); }

std::optional<double> FrameStats::passMs(std::string_view pass) const
{
    const auto found =
        std::find_if(passes.begin(), passes.end(), [&](const PassTiming& timing) { return timing.name == pass; });
    return found == passes.end() ? std::nullopt : found->gpuMs;
}

FrameStats SceneRenderer::render(const scene::Camera& camera, const FrameDesc& frame, ShadowPlans plans)
{
    gpuScene_.refresh(casterOptions(frame));
    return renderRefreshed(camera, frame, std::move(plans));
}

FrameStats SceneRenderer::renderRefreshed(const scene::Camera& camera, const FrameDesc& frame, ShadowPlans plans)
{
    const auto start = std::chrono::steady_clock::now();
    shadows::validate(frame.shadows);
    validate(frame.ambient);
    validate(frame.environment);
    checkPlansFitFrame(plans, frame.shadows);
    checkMsaa(frame, device_.capabilities());
    checkShadowPath(frame);
    prepareTargets(frame, plans);
    const std::optional<double> prefilterMs = environment_->use(frame.environment.image);
    FrameStats stats = prepareFrame(camera, frame, plans);
    stats.environmentPrefilterMs = prefilterMs;
    state_->stats = &stats;
    buildGraph(frame);
    graph_->compile();
    graph_->execute(*commands_);
    stats.recordingMs = millisecondsSince(start);
    device_.submit(*commands_);
    readDepthHistogram();
    stats.passes = graph_->timings();
    state_->stats = nullptr;
    return stats;
}

} // namespace penumbra::render
