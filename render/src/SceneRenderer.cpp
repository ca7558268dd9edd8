#include "penumbra/render/SceneRenderer.hpp"

#include "TextureSampling.hpp"
#include "passes/DepthPrepass.hpp"
#include "passes/LitDraws.hpp"
#include "passes/LitPipelines.hpp"
#include "passes/ScreenSpaceShadowPass.hpp"
#include "static/StaticMapHashes.hpp"
#include "static/StaticShadowCache.hpp"
#include "static/StaticTileCache.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"
#include "penumbra/shadows/DirectionalShadowUniforms.hpp"
#include "penumbra/shadows/LocalShadowUniforms.hpp"
#include "penumbra/shadows/ShadowCaster.hpp"
#include "penumbra/shadows/StaticShadowUniforms.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace penumbra::render {
namespace {

constexpr std::uint32_t kStandInAtlasSize = 16; // an atlas without tiles in use
constexpr glm::vec4 kBackground{0.2f, 0.22f, 0.26f, 1.0f}; // sRGB-encoded, as the lit shader writes
constexpr glm::vec4 kUndecided{1.0f, 1.0f, 1.0f, 0.0f}; // the visibility view where no shadow map decides

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

float aspectOf(const FrameDesc& frame) { return static_cast<float>(frame.width) / static_cast<float>(frame.height); }

shadows::ShadowCamera shadowCamera(const scene::Camera& camera, float aspect)
{
    const glm::vec3 up = glm::normalize(glm::cross(camera.right(), camera.forward));
    return {camera.position, camera.forward, up, camera.fovY, aspect, camera.nearPlane, camera.farPlane};
}

shadows::NormalBiasSide biasSide(scene::NormalBiasSide side)
{
    return side == scene::NormalBiasSide::Caster ? shadows::NormalBiasSide::Caster : shadows::NormalBiasSide::Receiver;
}

// A scene light's shadow filter: nullopt for the atlas's, else a shadows::ShadowFilter.
std::optional<shadows::ShadowFilter> lightFilter(std::int32_t filter, const std::string& what)
{
    if (filter == scene::kAtlasShadowFilter)
        return std::nullopt;
    if (filter < 0 || filter >= shadows::kShadowFilterCount)
        throw rhi::Error(fmt::format("{}: shadowFilter {} is out of range, allowed {} (the atlas's) or 0..{} ({})",
                                     what, filter, scene::kAtlasShadowFilter, shadows::kShadowFilterCount - 1,
                                     shadows::filterCommandNames()));
    return static_cast<shadows::ShadowFilter>(filter);
}

// A scene light's static shadow map mode: nullopt for the settings'.
std::optional<shadows::StaticShadowUpdate> staticUpdate(scene::ShadowUpdate update)
{
    switch (update) {
    case scene::ShadowUpdate::EveryFrame:
        return shadows::StaticShadowUpdate::EveryFrame;
    case scene::ShadowUpdate::OnChange:
        return shadows::StaticShadowUpdate::OnChange;
    case scene::ShadowUpdate::OnDemand:
        return shadows::StaticShadowUpdate::OnDemand;
    case scene::ShadowUpdate::Settings:
        break;
    }
    return std::nullopt;
}

std::vector<shadows::DirectionalShadowLightInput> shadowLights(const std::vector<scene::DirectionalLight>& lights)
{
    std::vector<shadows::DirectionalShadowLightInput> inputs;
    for (const scene::DirectionalLight& light : lights)
        inputs.push_back({light.direction, light.shadowStrength, light.nearPlaneOffset, light.normalBias,
                          light.slopeScaleBias, true, lightFilter(light.shadowFilter, "light '" + light.name + "'"),
                          light.angularDiameter, biasSide(light.normalBiasSide), staticUpdate(light.shadowUpdate)});
    return inputs;
}

std::vector<shadows::SpotShadowInput> spotShadowInputs(const std::vector<scene::SpotLight>& lights)
{
    std::vector<shadows::SpotShadowInput> inputs;
    for (const scene::SpotLight& l : lights)
        inputs.push_back({l.position, l.direction, l.range, l.outerAngle, l.shadowStrength, l.normalBias,
                          l.slopeScaleBias, l.shadowNearPlane,
                          lightFilter(l.shadowFilter, "spot light '" + l.name + "'"), l.sourceRadius,
                          biasSide(l.normalBiasSide), staticUpdate(l.shadowUpdate)});
    return inputs;
}

std::vector<shadows::PointShadowInput> pointShadowInputs(const std::vector<scene::PointLight>& lights)
{
    std::vector<shadows::PointShadowInput> inputs;
    for (const scene::PointLight& l : lights)
        inputs.push_back({l.position, l.range, l.shadowStrength, l.normalBias, l.slopeScaleBias, l.shadowNearPlane,
                          lightFilter(l.shadowFilter, "point light '" + l.name + "'"), l.sourceRadius,
                          biasSide(l.normalBiasSide), staticUpdate(l.shadowUpdate)});
    return inputs;
}

const char* kindName(shadows::LocalLightKind kind)
{
    return kind == shadows::LocalLightKind::Spot ? "spot light" : "point light";
}

const std::string& localLightName(const scene::Scene& scene, shadows::LocalLightKind kind, std::uint32_t index)
{
    return kind == shadows::LocalLightKind::Spot ? scene.spotLights[index].name : scene.pointLights[index].name;
}

// The lit pass's local lights: spot lights, then point lights, up to maxLitLocalLights.
void fillLocalLights(LitFrameUniforms& u, const scene::Scene& scene, const shadows::LocalShadowPlan& plan)
{
    std::uint32_t count = 0;
    for (std::size_t i = 0; i < scene.spotLights.size() && count < maxLitLocalLights; ++i, ++count) {
        const scene::SpotLight& l = scene.spotLights[i];
        // Smooth step of the cone: saturate(cos(angle) * a + b), 0 at the outer, 1 at the inner angle.
        const float cosOuter = std::cos(l.outerAngle);
        const float scale = 1.0f / std::max(std::cos(l.innerAngle) - cosOuter, 1e-3f);
        u.localPosition[count] = glm::vec4(l.position, 1.0f / (l.range * l.range));
        u.localColor[count] = glm::vec4(l.color * l.intensity, static_cast<float>(scene::LightKind::Spot));
        u.localAxis[count] = glm::vec4(l.direction, 0.0f);
        u.localShadow[count] = {scale, -cosOuter * scale, static_cast<float>(plan.spotTiles[i]), l.shadowStrength};
    }
    for (std::size_t i = 0; i < scene.pointLights.size() && count < maxLitLocalLights; ++i, ++count) {
        const scene::PointLight& l = scene.pointLights[i];
        u.localPosition[count] = glm::vec4(l.position, 1.0f / (l.range * l.range));
        u.localColor[count] = glm::vec4(l.color * l.intensity, static_cast<float>(scene::LightKind::Point));
        u.localShadow[count] = {0.0f, 0.0f, static_cast<float>(plan.pointShadows[i]), l.shadowStrength};
    }
    u.localLightCount = static_cast<int>(count);
}

const std::string& lightName(const scene::Scene& scene, shadows::ShadowLightKind kind, std::uint32_t index)
{
    switch (kind) {
    case shadows::ShadowLightKind::Spot:
        return scene.spotLights[index].name;
    case shadows::ShadowLightKind::Point:
        return scene.pointLights[index].name;
    case shadows::ShadowLightKind::Directional:
        break;
    }
    return scene.lights[index].name;
}

bool hasStaticMap(const shadows::StaticShadowPlan& plan, shadows::ShadowLightKind kind, std::uint32_t index)
{
    return std::any_of(plan.maps.begin(), plan.maps.end(), [&](const shadows::StaticShadowMap& map) {
        return map.kind == kind && map.lightIndex == index;
    });
}

shadows::ShadowLightKind shadowLightKind(shadows::LocalLightKind kind)
{
    return kind == shadows::LocalLightKind::Spot ? shadows::ShadowLightKind::Spot : shadows::ShadowLightKind::Point;
}

// What a light without realtime shadows has: nothing, or its static map alone.
const char* withoutRealtime(const ShadowPlans& plans, shadows::ShadowLightKind kind, std::uint32_t index)
{
    return hasStaticMap(plans.staticMaps, kind, index) ? "has static shadows only" : "has no shadows";
}

// Lights drawn without shadows, or not drawn at all, and why.
std::vector<std::string> frameNotes(const scene::Scene& scene, const ShadowPlans& plans)
{
    std::vector<std::string> notes;
    for (const shadows::ShadowPlanNote& note : plans.directional.report)
        notes.push_back(
            note.lightIndex
                ? fmt::format("light {} ('{}') {}: {}", *note.lightIndex, scene.lights[*note.lightIndex].name,
                              withoutRealtime(plans, shadows::ShadowLightKind::Directional, *note.lightIndex),
                              note.reason)
                : fmt::format("no shadows: {}", note.reason));
    for (std::size_t i = maxLitDirectionalLights; i < scene.lights.size(); ++i)
        notes.push_back(fmt::format("light {} ('{}') is not drawn: beyond the limit of {} directional lights", i,
                                    scene.lights[i].name, maxLitDirectionalLights));
    for (const shadows::LocalShadowNote& note : plans.local.report)
        notes.push_back(fmt::format("{} {} ('{}') {}: {}", kindName(note.kind), note.lightIndex,
                                    localLightName(scene, note.kind, note.lightIndex),
                                    withoutRealtime(plans, shadowLightKind(note.kind), note.lightIndex), note.reason));
    for (const shadows::StaticShadowNote& note : plans.staticMaps.report)
        notes.push_back(fmt::format("{} {} ('{}'): {}", shadows::shadowLightKindName(note.kind), note.lightIndex,
                                    lightName(scene, note.kind, note.lightIndex), note.reason));
    const std::size_t spots = scene.spotLights.size();
    for (std::size_t i = maxLitLocalLights; i < spots + scene.pointLights.size(); ++i) {
        const auto kind = i < spots ? shadows::LocalLightKind::Spot : shadows::LocalLightKind::Point;
        const auto index = static_cast<std::uint32_t>(i < spots ? i : i - spots);
        notes.push_back(fmt::format("{} {} ('{}') is not drawn: beyond the limit of {} spot and point lights",
                                    kindName(kind), index, localLightName(scene, kind, index), maxLitLocalLights));
    }
    return notes;
}

void checkFrameSize(const FrameDesc& frame)
{
    if (frame.width == 0 || frame.height == 0)
        throw rhi::Error(
            fmt::format("frame size {}x{}: width and height must be at least 1", frame.width, frame.height));
}

// A plan drawn into atlases of other sizes would put its tiles in the wrong texels.
void checkPlansFitFrame(const ShadowPlans& plans, const shadows::ShadowSettings& settings)
{
    if (plans.directional.atlas.atlasSize() != settings.directional.atlasSize)
        throw rhi::Error(fmt::format("shadow plans: the directional plan is for a {}-texel atlas, the frame's "
                                     "directional.atlasSize is {}",
                                     plans.directional.atlas.atlasSize(), settings.directional.atlasSize));
    if (plans.local.atlas.atlasSize() != settings.local.atlasSize)
        throw rhi::Error(fmt::format("shadow plans: the spot and point plan is for a {}-texel atlas, the frame's "
                                     "local.atlasSize is {}",
                                     plans.local.atlas.atlasSize(), settings.local.atlasSize));
    if (!plans.local.cubes.empty() && settings.local.pointMode != shadows::PointShadowMode::CubeMap)
        throw rhi::Error("shadow plans: the spot and point plan has shadow cube maps, the frame's local.pointMode "
                         "is atlas");
    if (plans.local.cubes.size() > shadows::maxShadowCubes)
        throw rhi::Error(fmt::format("shadow plans: {} shadow cube maps, at most {}", plans.local.cubes.size(),
                                     shadows::maxShadowCubes));
}

bool isStatic(const std::vector<std::uint32_t>& staticCasters, std::uint32_t caster)
{
    return std::binary_search(staticCasters.begin(), staticCasters.end(), caster);
}

// RealtimeCasters::Dynamic: the tiles' static casters, which the realtime atlases take from StaticTileCache, and
// the tiles without them, which the passes draw over it.
struct SplitTiles {
    std::vector<shadows::ShadowTileDraw> directional;
    std::vector<shadows::ShadowTileDraw> local;
};

SplitTiles splitStaticCasters(ShadowPlans& plans, const std::vector<std::uint32_t>& staticCasters)
{
    SplitTiles split{shadows::DirectionalShadowPass::tileDraws(plans.directional),
                     shadows::LocalShadowPass::tileDraws(plans.local)};
    for (std::vector<shadows::ShadowTileDraw>* tiles : {&split.directional, &split.local})
        for (shadows::ShadowTileDraw& tile : *tiles)
            std::erase_if(tile.casters, [&](std::uint32_t i) { return !isStatic(staticCasters, i); });
    const auto drop = [&](std::vector<std::uint32_t>& casters) {
        std::erase_if(casters, [&](std::uint32_t i) { return isStatic(staticCasters, i); });
    };
    for (shadows::ShadowedDirectionalLight& light : plans.directional.lights)
        for (shadows::DirectionalCascadePlan& cascade : light.cascades)
            drop(cascade.casters.casters);
    for (shadows::LocalAtlasTile& tile : plans.local.tiles)
        drop(tile.view.casters);
    return split;
}

std::unique_ptr<rhi::Texture> colorTarget(rhi::Device& device, const FrameDesc& frame, const std::string& name)
{
    return device.createTexture({.width = frame.width,
                                 .height = frame.height,
                                 .format = kLitColorFormat,
                                 .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget,
                                 .debugName = name});
}

std::unique_ptr<rhi::Texture> depthTarget(rhi::Device& device, const FrameDesc& frame, std::uint32_t samples,
                                          const std::string& name)
{
    // The single-sampled depth is what the screen-space shadow collection reads.
    return device.createTexture({.width = frame.width,
                                 .height = frame.height,
                                 .format = kLitDepthFormat,
                                 .usage = samples == 1 ? rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget
                                                       : rhi::TextureUsage::RenderTarget,
                                 .samples = samples,
                                 .debugName = name});
}

// FrameDesc::msaa: 1, or a count the device offers for both of the lit pass's targets.
void checkMsaa(const FrameDesc& frame, const rhi::Capabilities& caps)
{
    if (frame.msaa != 1 && frame.msaa != 2 && frame.msaa != 4 && frame.msaa != 8)
        throw rhi::Error(fmt::format("FrameDesc::msaa: {} is not 1, 2, 4 or 8", frame.msaa));
    const std::array targets{kLitColorFormat, kLitDepthFormat};
    const std::uint32_t offered = caps.sampleCounts(targets);
    if ((offered & frame.msaa) == 0)
        throw rhi::UnsupportedError(fmt::format("msaa {}: {} offers {} samples per pixel for the lit pass ({} colour, "
                                                "{} depth)",
                                                frame.msaa, caps.device, rhi::sampleCountList(offered),
                                                rhi::formatName(kLitColorFormat), rhi::formatName(kLitDepthFormat)));
}

void checkShadowPath(const FrameDesc& frame)
{
    if (frame.shadowPath == ShadowPath::ScreenSpace && !frame.depthPrepass)
        throw rhi::Error("FrameDesc::shadowPath: the screen-space shadow path collects shadows from the depth "
                         "prepass's depth; it needs FrameDesc::depthPrepass");
}

// Why a screen-space frame's directional shadows cannot all be collected (a light past the collected ones has
// realtime or static shadows), or nullopt.
std::optional<std::string> uncollectedShadows(const scene::Scene& scene, const shadows::DirectionalShadowPlan& plan,
                                              const shadows::StaticShadowUniforms& staticMaps)
{
    const std::size_t count = std::min<std::size_t>(plan.shadowSlots.size(), maxLitDirectionalLights);
    for (std::size_t i = maxCollectedDirectionalLights; i < count; ++i)
        if (plan.shadowSlots[i] >= 0 || staticMaps.directionalLights[i].x >= 0.0f)
            return fmt::format("screen-space shadows: directional light {} ('{}') has shadows, but the screen-space "
                               "shadow texture holds lights 0 to {}; the frame is drawn with forward shadows",
                               i, scene.lights[i].name, maxCollectedDirectionalLights - 1);
    return std::nullopt;
}

} // namespace

SceneRenderer::SceneRenderer(rhi::Device& device, const scene::Scene& scene)
    : device_(device), gpuScene_(device, scene), shadowPass_(device, GpuScene::vertexFormat()),
      localShadowPass_(device, GpuScene::vertexFormat()), litVertex_(device.createShader(litShader("lit.vert"))),
      litPipelines_(std::make_unique<LitPipelines>(device, *litVertex_, 1)),
      depthPrepass_(std::make_unique<DepthPrepass>(device, kLitDepthFormat, 1)),
      staticShadows_(std::make_unique<StaticShadowCache>(device, GpuScene::vertexFormat())),
      commands_(device.createCommandList()),
      timestamps_(device.capabilities().timestamps ? device.createTimestampQueries(8) : nullptr),
      uniforms_(device, "lit pass uniforms"), instances_(device, "lit pass instances")
{
    directionalStaticTiles_ =
        std::make_unique<StaticTileCache>(device, GpuScene::vertexFormat(), "directional atlas, static casters");
    localStaticTiles_ =
        std::make_unique<StaticTileCache>(device, GpuScene::vertexFormat(), "local atlas, static casters");
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
        const bool isDirectional = map.kind == shadows::ShadowLightKind::Directional;
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
    if (!localAtlas_ || localAtlas_->size() != localSize || localAtlas_->format() != local.atlasFormat)
        localAtlas_ =
            std::make_unique<shadows::ShadowAtlas>(device_, localSize, local.atlasFormat, "local shadow atlas");
    // Cube-map mode keeps room for every cube it may plan; otherwise one small cube stands in for the binding.
    const bool cubeMode = local.pointMode == shadows::PointShadowMode::CubeMap;
    const std::uint32_t faceSize = cubeMode ? local.cubeMapSize : 16;
    const std::uint32_t cubeCount = cubeMode ? shadows::maxShadowCubes : 1;
    if (!shadowCubes_ || shadowCubes_->faceSize() != faceSize || shadowCubes_->cubeCount() != cubeCount ||
        shadowCubes_->format() != local.atlasFormat)
        shadowCubes_ = std::make_unique<shadows::ShadowCubes>(device_, faceSize, cubeCount, local.atlasFormat);
    if (frame.msaa > 1 && (!multisampledLitPipelines_ || multisampledLitPipelines_->samples() != frame.msaa))
        multisampledLitPipelines_ = std::make_unique<LitPipelines>(device_, *litVertex_, frame.msaa);
    if (depthPrepass_->samples() != frame.msaa)
        depthPrepass_ = std::make_unique<DepthPrepass>(device_, kLitDepthFormat, frame.msaa);
    const bool firstScreenSpace = frame.shadowPath == ShadowPath::ScreenSpace && !screenSpace_;
    if (firstScreenSpace) {
        receiverPrepass_ = std::make_unique<DepthPrepass>(device_, kLitDepthFormat, 1, true);
        screenSpace_ = std::make_unique<ScreenSpaceShadowPass>(device_);
    }
    const std::uint32_t litSamples = multisampledColor_ ? multisampledColor_->desc().samples : 1;
    if (lit_ && lit_->desc().width == frame.width && lit_->desc().height == frame.height && litSamples == frame.msaa) {
        if (firstScreenSpace)
            screenSpace_->prepare(*depth_);
        return;
    }
    lit_ = colorTarget(device_, frame, "lit image");
    cascades_ = colorTarget(device_, frame, "cascade view");
    visibility_ = colorTarget(device_, frame, "visibility view");
    depth_ = depthTarget(device_, frame, 1, "lit depth");
    if (screenSpace_)
        screenSpace_->prepare(*depth_);
    multisampledColor_.reset();
    multisampledDepth_.reset();
    if (frame.msaa > 1) {
        multisampledColor_ = device_.createTexture({.width = frame.width,
                                                    .height = frame.height,
                                                    .format = kLitColorFormat,
                                                    .usage = rhi::TextureUsage::RenderTarget,
                                                    .samples = frame.msaa,
                                                    .debugName = "lit image (multisampled)"});
        multisampledDepth_ = depthTarget(device_, frame, frame.msaa, "lit depth (multisampled)");
    }
    const rhi::Attachment litColor{multisampledColor_ ? multisampledColor_.get() : lit_.get(), 0};
    const rhi::Attachment litDepth{multisampledDepth_ ? multisampledDepth_.get() : depth_.get(), 0};
    const rhi::Attachment cascadeColor{cascades_.get(), 0};
    litTarget_ = device_.createFramebuffer({.colors = {&litColor, 1}, .depth = litDepth, .debugName = "lit"});
    prepassTarget_ = device_.createFramebuffer({.depth = litDepth, .debugName = "depth prepass"});
    cascadeTarget_ = device_.createFramebuffer(
        {.colors = {&cascadeColor, 1}, .depth = {depth_.get(), 0}, .debugName = "cascade view"});
    const rhi::Attachment visibilityColor{visibility_.get(), 0};
    visibilityTarget_ = device_.createFramebuffer(
        {.colors = {&visibilityColor, 1}, .depth = {depth_.get(), 0}, .debugName = "visibility view"});
}

LitFrameUniforms SceneRenderer::frameUniforms(const scene::Camera& camera, const FrameDesc& frame, LitView view) const
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
        u.lightColor[i] = glm::vec4(lights[i].color * lights[i].intensity, 0.0f);
        u.lightDirection[i] = glm::vec4(glm::normalize(lights[i].direction), static_cast<float>(plan_.shadowSlots[i]));
    }
    u.ambient = glm::vec4(frame.ambient.sky(), 0.0f);
    u.ambientGround = glm::vec4(frame.ambient.below(), 0.0f);
    u.directionalLightCount = static_cast<int>(count);
    u.litView = static_cast<int>(view);
    fillLocalLights(u, gpuScene_.scene(), localPlan_);
    return u;
}

// The lit pass's order: directional lights, then spot lights, then point lights (fillLocalLights).
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
    if (local >= maxLitLocalLights)
        throw rhi::Error(fmt::format("visibility view: {} {} is not drawn (at most {} spot and point lights)", kind,
                                     light.index, maxLitLocalLights));
    return static_cast<int>(directional + local);
}

void SceneRenderer::bindShadowMaps(rhi::CommandList& commands, const rhi::UniformSlice& shadowUniforms,
                                   const rhi::UniformSlice& localShadowUniforms,
                                   const rhi::UniformSlice& staticShadowUniforms) const
{
    rhi::bindUniform(commands, kLitShadowBinding, shadowUniforms);
    commands.bindTexture(kLitAtlasBinding, atlas_->texture(), atlas_->sampler());
    rhi::bindUniform(commands, kLitLocalShadowBinding, localShadowUniforms);
    commands.bindTexture(kLitLocalAtlasBinding, localAtlas_->texture(), localAtlas_->sampler());
    commands.bindTexture(kLitShadowCubesBinding, shadowCubes_->texture(), shadowCubes_->sampler());
    commands.bindTexture(kLitShadowCubeDepthsBinding, shadowCubes_->texture(), shadowCubes_->depthSampler());
    rhi::bindUniform(commands, kLitStaticShadowBinding, staticShadowUniforms);
    const shadows::ShadowAtlas& staticDirectional = staticShadows_->directionalAtlas();
    const shadows::ShadowAtlas& staticLocal = staticShadows_->localAtlas();
    commands.bindTexture(kLitStaticDirectionalAtlasBinding, staticDirectional.texture(), staticDirectional.sampler());
    commands.bindTexture(kLitStaticLocalAtlasBinding, staticLocal.texture(), staticLocal.sampler());
}

std::uint32_t SceneRenderer::recordLitPass(rhi::CommandList& commands, const rhi::Framebuffer& target,
                                           LitPipelines& pipelines, const rhi::UniformSlice& frameSlice,
                                           const LitShaderFeatures& features, const rhi::UniformSlice& shadowUniforms,
                                           const rhi::UniformSlice& localShadowUniforms,
                                           const rhi::UniformSlice& staticShadowUniforms)
{
    const scene::Scene& scene = gpuScene_.scene();
    const bool visibility = features.view == LitView::Visibility;
    const bool prepassed = features.depthPrepassed;
    // The visibility view reports shadows on every surface: blended ones are drawn opaque there, so the alpha
    // channel keeps saying whether a shadow map decides the pixel.
    commands.beginPass(
        {.framebuffer = &target, .clearColor = visibility ? kUndecided : kBackground, .clearDepth = !prepassed});
    const DirectionalShadowSource directionalShadows = features.directionalShadows;
    const rhi::Pipeline* bound = nullptr;
    for (const LitDraw& draw : litDraws_) {
        const scene::Object& object = scene.objects[draw.object];
        const scene::Material& material = scene.materialOf(object);
        const bool blend = material.blend && !visibility;
        LitShaderFeatures objectFeatures = features;
        objectFeatures.materialMaps = litMaterialMaps(material);
        const rhi::Pipeline* pipeline = &pipelines.choose(objectFeatures, material.doubleSided, blend);
        if (pipeline != bound) {
            // Every binding again: a pipeline change may drop what was bound (OpenGL program, Vulkan layout).
            commands.bindPipeline(*pipeline);
            rhi::bindUniform(commands, kLitFrameBinding, frameSlice);
            bindShadowMaps(commands, shadowUniforms, localShadowUniforms, staticShadowUniforms);
            if (directionalShadows != DirectionalShadowSource::Forward)
                commands.bindTexture(kLitScreenSpaceShadowsBinding, screenSpace_->shadows(), screenSpace_->sampler());
            // Only where the lit pass does not draw into it: multisampled, the single-sampled depth is no attachment.
            if (directionalShadows == DirectionalShadowSource::ScreenSpaceEdges)
                commands.bindTexture(kLitScreenSpaceDepthBinding, screenSpace_->depth(), screenSpace_->sampler());
            bound = pipeline;
        }
        rhi::bindUniform(commands, kLitObjectBinding, draw.uniforms);
        gpuScene_.drawWithMaps(commands, object, kLitMaterialMapBinding, kLitCoverageMapBinding, draw.instances,
                               draw.instanceCount);
    }
    commands.endPass();
    return static_cast<std::uint32_t>(litDraws_.size());
}

ShadowPlans SceneRenderer::planShadows(const scene::Camera& camera, const FrameDesc& frame) const
{
    checkFrameSize(frame);
    const float aspect = aspectOf(frame);
    const scene::Scene& scene = gpuScene_.scene();
    const std::vector<shadows::Bounds> bounds = gpuScene_.casterBounds();
    const std::vector<shadows::DirectionalShadowLightInput> lights = shadowLights(scene.lights);
    const std::vector<shadows::SpotShadowInput> spots = spotShadowInputs(scene.spotLights);
    const std::vector<shadows::PointShadowInput> points = pointShadowInputs(scene.pointLights);
    const std::vector<std::uint32_t> staticCasters = gpuScene_.staticCasters();
    return {shadows::planDirectionalShadows(frame.shadows, device_.conventions(), shadowCamera(camera, aspect), lights,
                                            bounds),
            shadows::planLocalShadows(frame.shadows, device_.conventions(), shadowCamera(camera, aspect), spots, points,
                                      bounds),
            shadows::planStaticShadows(frame.shadows, device_.conventions(), lights, spots, points,
                                       {bounds, staticCasters})};
}

FrameStats SceneRenderer::render(const scene::Camera& camera, const FrameDesc& frame)
{
    const auto start = std::chrono::steady_clock::now();
    ShadowPlans plans = planShadows(camera, frame);
    const double planningMs = millisecondsSince(start);
    FrameStats stats = render(camera, frame, std::move(plans));
    stats.planningMs = planningMs;
    return stats;
}

FrameStats SceneRenderer::render(const scene::Camera& camera, const FrameDesc& frame, ShadowPlans plans)
{
    const auto start = std::chrono::steady_clock::now();
    shadows::validate(frame.shadows);
    validate(frame.ambient);
    checkPlansFitFrame(plans, frame.shadows);
    checkMsaa(frame, device_.capabilities());
    checkShadowPath(frame);
    const AnisotropyChoice anisotropy = chooseAnisotropy(frame.maxAnisotropy, device_.capabilities());
    const int visibilityLight = frame.visibilityOf ? litLightIndex(*frame.visibilityOf) : -1;
    prepareTargets(frame, plans);
    gpuScene_.setMaxAnisotropy(anisotropy.value);
    notes_ = frameNotes(gpuScene_.scene(), plans);
    if (anisotropy.note && !gpuScene_.scene().textures.empty())
        notes_.push_back(*anisotropy.note);
    // Every static map mode, the settings' or a light's own, keeps static depth for the realtime tiles.
    const bool keepsStaticMaps = shadows::hasStaticMaps(frame.shadows) || !plans.staticMaps.maps.empty();
    const bool dynamicOnly =
        keepsStaticMaps && frame.shadows.staticMaps.realtimeCasters == shadows::RealtimeCasters::Dynamic;
    const SplitTiles staticTiles = dynamicOnly ? splitStaticCasters(plans, gpuScene_.staticCasters()) : SplitTiles{};
    plan_ = std::move(plans.directional);
    localPlan_ = std::move(plans.local);

    if (staticShadows_->baked()) {
        if (!keepsStaticMaps)
            throw rhi::Error("baked shadows: the frame's settings keep no static maps (static.update is everyFrame, "
                             "and so is every light's own mode); set it to onChange or onDemand");
        staticShadows_->checkBake(plans.staticMaps, staticMapHashes(gpuScene_.scene(), plans.staticMaps));
    }
    FrameStats stats;
    stats.notes = notes_;
    for (const shadows::ShadowedDirectionalLight& light : plan_.lights)
        for (const shadows::DirectionalCascadePlan& cascade : light.cascades)
            stats.casterDrawsWithoutCullingBias += cascade.casters.overlapping;

    uniforms_.reset();
    instances_.reset();
    const scene::Scene& scene = gpuScene_.scene();
    litDraws_ = litDraws(gpuScene_, camera.position, scene::ViewFrustum(camera, aspectOf(frame)), frame.instancedDraws,
                         uniforms_, instances_);
    const rhi::UniformSlice shadowUniforms = uniforms_.push(plan_.uniforms);
    const rhi::UniformSlice localShadowUniforms = uniforms_.push(localPlan_.uniforms);
    gpuScene_.casters(casters_);
    const std::vector<shadows::ShadowCaster>& casters = casters_;
    if (!frame.instancedDraws)
        for (shadows::ShadowCaster& caster : casters_)
            caster.drawGroup = shadows::kNoDrawGroup;
    rhi::CommandList& commands = *commands_;
    if (timestamps_)
        commands.writeTimestamp(*timestamps_, 0);
    const StaticMapDraws staticDraws =
        staticShadows_->update(commands, frame.shadows, std::move(plans.staticMaps), casters, staticUpdateRequested_);
    staticUpdateRequested_ = false;
    stats.staticCasterDraws = staticDraws.casterDraws;
    for (const StaticMapUpdate& update : staticDraws.updates)
        stats.staticMapUpdates.push_back(fmt::format("{} {} ('{}'): {}", shadows::shadowLightKindName(update.kind),
                                                     update.lightIndex,
                                                     lightName(scene, update.kind, update.lightIndex), update.reason));
    const rhi::UniformSlice staticShadowUniforms = uniforms_.push(staticShadows_->plan().uniforms);
    if (timestamps_)
        commands.writeTimestamp(*timestamps_, 1);
    // Dynamic casters only: the tiles' static depth comes from the caches, then the passes draw over it.
    const bool cachedDirectional = dynamicOnly && !staticTiles.directional.empty();
    const bool cachedLocal = dynamicOnly && !staticTiles.local.empty();
    if (cachedDirectional)
        stats.staticCasterDraws += directionalStaticTiles_->update(commands, *atlas_, staticTiles.directional, casters);
    stats.casterDraws = shadowPass_.record(commands, *atlas_, plan_, casters, !cachedDirectional);
    if (timestamps_)
        commands.writeTimestamp(*timestamps_, 2);
    if (cachedLocal)
        stats.staticCasterDraws += localStaticTiles_->update(commands, *localAtlas_, staticTiles.local, casters);
    stats.localCasterDraws =
        localShadowPass_.record(commands, *localAtlas_, *shadowCubes_, localPlan_, casters, !cachedLocal);
    if (timestamps_)
        commands.writeTimestamp(*timestamps_, 3);
    const LitFrameUniforms litFrameUniforms = frameUniforms(camera, frame, LitView::Lit);
    const rhi::UniformSlice litFrame = uniforms_.push(litFrameUniforms);
    LitShaderFeatures features =
        frameShaderFeatures(litFrameUniforms, plan_.uniforms, localPlan_.uniforms, staticShadows_->plan().uniforms);
    const bool multisampled = frame.msaa > 1;
    std::optional<std::string> uncollected;
    if (frame.shadowPath == ShadowPath::ScreenSpace)
        uncollected = uncollectedShadows(scene, plan_, staticShadows_->plan().uniforms);
    if (uncollected) {
        notes_.push_back(*uncollected);
        stats.notes.push_back(*uncollected);
    }
    const bool screenSpace = frame.shadowPath == ShadowPath::ScreenSpace && !uncollected;
    // Single-sampled, the receiver prepass is the depth prepass; with MSAA it adds the one-sample depth the
    // collection reads.
    if (frame.depthPrepass && (multisampled || !screenSpace))
        stats.depthPrepassDraws += depthPrepass_->record(commands, *prepassTarget_, gpuScene_, litDraws_, litFrame);
    if (screenSpace)
        stats.depthPrepassDraws +=
            receiverPrepass_->record(commands, screenSpace_->receiverTarget(), gpuScene_, litDraws_, litFrame);
    if (timestamps_)
        commands.writeTimestamp(*timestamps_, 4);
    if (screenSpace) {
        screenSpace_->begin(commands, features,
                            uniforms_.push(screenSpaceShadowUniforms(litFrameUniforms, frame.width, frame.height)));
        bindShadowMaps(commands, shadowUniforms, localShadowUniforms, staticShadowUniforms);
        screenSpace_->draw(commands);
        features.directionalShadows =
            multisampled ? DirectionalShadowSource::ScreenSpaceEdges : DirectionalShadowSource::ScreenSpace;
    }
    if (timestamps_)
        commands.writeTimestamp(*timestamps_, 5);
    features.depthPrepassed = frame.depthPrepass;
    stats.litDraws = recordLitPass(commands, *litTarget_, multisampled ? *multisampledLitPipelines_ : *litPipelines_,
                                   litFrame, features, shadowUniforms, localShadowUniforms, staticShadowUniforms);
    // The debug views draw single-sampled without the prepass, with forward shadows: they clear the single-sampled
    // depth.
    features.depthPrepassed = false;
    features.directionalShadows = DirectionalShadowSource::Forward;
    features.view = LitView::Cascades;
    if (timestamps_)
        commands.writeTimestamp(*timestamps_, 6);
    if (multisampled)
        commands.resolveTexture(*multisampledColor_, *lit_);
    if (timestamps_)
        commands.writeTimestamp(*timestamps_, 7);
    if (frame.cascadeView)
        recordLitPass(commands, *cascadeTarget_, *litPipelines_,
                      uniforms_.push(frameUniforms(camera, frame, LitView::Cascades)), features, shadowUniforms,
                      localShadowUniforms, staticShadowUniforms);
    if (frame.visibilityOf) {
        LitFrameUniforms u = frameUniforms(camera, frame, LitView::Visibility);
        u.visibilityLight = visibilityLight;
        // The visibility view of any light, with every part of the shader: a debug view, not worth a variant each.
        recordLitPass(commands, *visibilityTarget_, *litPipelines_, uniforms_.push(u),
                      LitShaderFeatures{.view = LitView::Visibility}, shadowUniforms, localShadowUniforms,
                      staticShadowUniforms);
    }
    stats.recordingMs = millisecondsSince(start);
    device_.submit(commands);
    if (timestamps_) {
        const std::vector<double> ns = device_.readTimestamps(*timestamps_);
        stats.staticAtlasPassMs = (ns[1] - ns[0]) * 1e-6;
        stats.atlasPassMs = (ns[2] - ns[1]) * 1e-6;
        stats.localAtlasPassMs = (ns[3] - ns[2]) * 1e-6;
        if (frame.depthPrepass)
            stats.depthPrepassMs = (ns[4] - ns[3]) * 1e-6;
        if (screenSpace)
            stats.screenSpaceShadowsMs = (ns[5] - ns[4]) * 1e-6;
        stats.litPassMs = (ns[6] - ns[5]) * 1e-6;
        if (multisampled)
            stats.resolvePassMs = (ns[7] - ns[6]) * 1e-6;
    }
    return stats;
}

} // namespace penumbra::render
