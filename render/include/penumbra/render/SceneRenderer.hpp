#pragma once

#include "penumbra/render/AmbientLight.hpp"
#include "penumbra/render/Environment.hpp"
#include "penumbra/render/FramePass.hpp"
#include "penumbra/render/GpuScene.hpp"
#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/UniformArena.hpp"
#include "penumbra/scene/Scene.hpp"
#include "penumbra/shadows/DirectionalShadowPass.hpp"
#include "penumbra/shadows/DirectionalShadowPlanner.hpp"
#include "penumbra/shadows/LocalShadowPass.hpp"
#include "penumbra/shadows/LocalShadowPlanner.hpp"
#include "penumbra/shadows/ShadowAtlas.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"
#include "penumbra/shadows/StaticShadowBake.hpp"
#include "penumbra/shadows/StaticShadowPlanner.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::render {

class ApplicationPasses;
class ContactShadowPass;
class DepthPrepass;
class DepthReduction;
class EnvironmentMaps;
class FrameGraph;
class GpuSkinning;
class GpuViewCulling;
class LitPipelines;
class LocalLightTextures;
class LocalTileCache;
class ScreenSpaceShadowPass;
class StaticShadowCache;
class StaticTileCache;
struct FrameState;
struct LitDraw;

// Where the lit pass's directional shadows are evaluated. Forward: in the lit pass, per fragment. ScreenSpace: after
// the depth prepass, one full-screen pass collects the cascaded shadows of directional lights 0 to
// maxCollectedDirectionalLights - 1 into a screen-space shadow texture (SceneRenderer::screenSpaceShadowImage()),
// which the lit pass reads at its pixel; the same picture as Forward. Spot and point shadows stay forward.
enum class ShadowPath : std::uint8_t { Forward, ScreenSpace };

// What one frame of SceneRenderer::render draws: its size, shadow settings, lighting and the passes' options.
struct FrameDesc {
    std::uint32_t width = 1280;
    std::uint32_t height = 720;
    shadows::ShadowSettings shadows;
    // Lights surfaces without a direct light, and only without an environment.
    AmbientLight ambient;
    // Image-based lighting; none by default (the ambient light instead). Prefiltered once per image (by pointer).
    EnvironmentLight environment;
    bool cascadeView = false; // also render the lit image tinted by cascade index
    // Also render this light's raw shadow-map visibility (SceneRenderer::visibilityImage()): the filtered
    // shadow in red, green and blue (1 = lit) before strength and fades, and in alpha 1 where its shadow map
    // decides the pixel (the light reaches it, a cascade or tile covers it, the material receives shadows).
    std::optional<scene::LightRef> visibilityOf;
    // Anisotropic filtering of the scene's trilinear textures, at least 1 (off); more than the device offers is
    // clamped to its limit (1 where it has none), and the frame's notes say so.
    float maxAnisotropy = 8.0f;
    // Draw opaque and clip geometry depth-only first (render/src/passes/DepthPrepass.hpp): the lit pass then tests
    // depth for equality and shades each visible pixel once instead of once per overlapping surface.
    bool depthPrepass = true;
    // Samples per pixel of the lit pass and its depth prepass: 1 (off), 2, 4 or 8, a count the device offers for
    // kLitColorFormat and kLitDepthFormat render targets (rhi::Capabilities::sampleCounts); others throw
    // rhi::UnsupportedError listing the counts it offers. Above 1 the pass draws into multisampled colour and depth
    // and resolves the colour into litImage(), so geometry edges are anti-aliased; shading still runs once per pixel,
    // and alpha-tested edges stay as hard as their discard (no alpha to coverage). The cascade and visibility views
    // stay single-sampled.
    std::uint32_t msaa = 1;
    // ShadowPath::ScreenSpace needs depthPrepass (render() throws rhi::Error without it). A frame whose directional
    // lights past the collected ones have shadows is drawn Forward, and its notes say so. With msaa above 1 the
    // collection is single-sampled, per pixel; fragments on geometry edges (not covering all their samples, or not
    // the collected surface) evaluate their shadows forward instead of taking the surface behind's.
    ShadowPath shadowPath = ShadowPath::Forward;
    // Objects that share a mesh and material are drawn as the instances of one draw in the depth prepass, the lit
    // pass and the shadow passes (each view's culled casters of one draw group), so that draws grow with distinct
    // meshes, not objects. False: a draw per object, the same pictures.
    bool instancedDraws = true;
};

// What a frame drew and what it cost: CPU and GPU times, draws, static map updates and notes.
struct FrameStats {
    // CPU time: the shadow planning of render(camera, frame) (0 where the caller planned), and recording the frame's
    // commands (render()'s work up to the submission, which then runs them).
    double planningMs = 0.0;
    double recordingMs = 0.0;
    // Draws issued by the depth prepass (the receiver prepass of ScreenSpace too) and by the lit pass (without the
    // cascade and visibility views); with the view culled on the GPU, every lit draw group's indirect draw, in view
    // or not.
    std::uint32_t depthPrepassDraws = 0;
    std::uint32_t litDraws = 0;
    std::uint32_t casterDraws = 0; // issued into the directional atlas
    std::uint32_t casterDrawsWithoutCullingBias = 0; // casters overlapping each cascade's light box
    std::uint32_t localCasterDraws = 0; // issued into the spot and point shadows
    // The passes that ran, in order, each with its GPU time where the device has timestamps (FrameResources.hpp
    // names the built-in ones).
    std::vector<PassTiming> passes;
    // Static shadow maps (ShadowSettings::staticMaps): the static caster draws this frame (into the static maps and,
    // with RealtimeCasters::Dynamic, into the realtime tiles' cached static depth), and which static maps were drawn
    // and why ("spot light 0 ('lamp'): a static caster in its view changed").
    std::uint32_t staticCasterDraws = 0;
    std::vector<std::string> staticMapUpdates;
    // Spot and point shadows are cached per light: the local atlas's tiles drawn this frame and those kept from an
    // earlier one (the cube faces of PointShadowMode::CubeMap are drawn every frame and not counted), and the lights
    // drawn again and why ("spot light 3 ('lamp'): a caster in its view changed").
    std::uint32_t localTilesDrawn = 0;
    std::uint32_t localTilesCached = 0;
    std::vector<std::string> localShadowUpdates;
    // The scene's lights (directional, spot and point) drawn with a shadow, realtime or static, and without one.
    std::uint32_t shadowedLights = 0;
    std::uint32_t lightsWithoutShadow = 0;
    // The realtime local atlas (shadows::ShadowAtlasPack): the share of its texels in tiles, the share of its free
    // texels outside the largest free square (fragmentation), and the lights whose tiles are smaller than they asked.
    float localAtlasUsed = 0.0f;
    float localAtlasFragmentation = 0.0f;
    std::uint32_t localLightsLowered = 0;
    // Lights drawn without shadows, or not drawn at all, and why; textures sampled with less anisotropy than
    // asked for (the same as SceneRenderer::notes()).
    std::vector<std::string> notes;
    // Where this frame prefiltered a new FrameDesc::environment image: the milliseconds it took (CPU and GPU, waited
    // for), before the frame's own work.
    std::optional<double> environmentPrefilterMs;

    // The GPU time of the pass of that name; nullopt where it did not run or the device has no timestamps.
    std::optional<double> passMs(std::string_view pass) const;
};

// The CPU half of a frame (scene -> shadow planning) that render() draws. An application may edit the plans
// in between (matrices of its own, a plan kept from an earlier frame) as long as their atlas sizes and
// point mode stay those of the frame's settings.
struct ShadowPlans {
    shadows::DirectionalShadowPlan directional;
    shadows::LocalShadowPlan local;
    shadows::StaticShadowPlan staticMaps; // empty without static maps (StaticShadowUpdate::EveryFrame)
};

// Draws a scene with cascaded directional shadows and spot and point shadows: plan (CPU) -> caster
// passes into the directional and the local atlas -> lit pass (and optionally the cascade view). One submission per
// frame; the results stay readable until the next render().
class SceneRenderer {
public:
    // The scene must outlive the renderer; it is validated and its meshes uploaded here.
    SceneRenderer(rhi::Device& device, const scene::Scene& scene);
    ~SceneRenderer();

    // Throws rhi::Error for settings out of range (naming the field).
    ShadowPlans planShadows(const scene::Camera& camera, const FrameDesc& frame) const;

    // render(camera, frame, planShadows(camera, frame)).
    FrameStats render(const scene::Camera& camera, const FrameDesc& frame);
    // Throws rhi::Error for settings or ambient light out of range (naming the field; maxAnisotropy below 1 too), a
    // zero-sized frame, plans whose atlases do not match the frame's settings, a visibility view of a light the lit
    // pass does not draw, or ShadowPath::ScreenSpace without the depth prepass; rhi::UnsupportedError for an msaa count
    // the device does not offer.
    FrameStats render(const scene::Camera& camera, const FrameDesc& frame, ShadowPlans plans);

    // The last frame's lit picture (kLitColorFormat, single-sampled).
    const rhi::Texture& litImage() const { return *lit_; }
    // The scene's buffers, textures and samplers as the last frame drew them.
    const GpuScene& gpuScene() const { return gpuScene_; }
    // The last FrameDesc::cascadeView frame's picture tinted by cascade.
    const rhi::Texture& cascadeImage() const { return *cascades_; }
    // The last FrameDesc::visibilityOf frame's raw shadow-map visibility of that light.
    const rhi::Texture& visibilityImage() const { return *visibility_; }
    // The last ShadowPath::ScreenSpace frame's screen-space shadow texture: RGBA32F, channel i directional light i's
    // attenuation at the pixel's surface (1 = lit; 1 where nothing is drawn). Throws rhi::Error before such a frame.
    const rhi::Texture& screenSpaceShadowImage() const;
    // 16 texels wide where the last frame used no tile of it (no shadowed directional light).
    const shadows::ShadowAtlas& atlas() const { return *atlas_; }
    // The directional plan the last frame drew.
    const shadows::DirectionalShadowPlan& plan() const { return plan_; }
    // The histogram of the visible depths the next directional.projection depthFit frame fits its cascades to: the
    // last depth-fit frame's (a reduction of its depth, shadows::DepthHistogram); nullopt before such a frame (depthFit
    // is then the close fit over the usual splits).
    const std::optional<shadows::DepthHistogram>& depthHistogram() const { return depthHistogram_; }
    // The histogram's range: the start of its first bin with samples and the end of its last.
    std::optional<shadows::ViewDepthRange> visibleDepths() const;
    // Spot and point shadows: tiles of this atlas (16 texels wide where the last frame used none).
    const shadows::ShadowAtlas& localAtlas() const { return *localAtlas_; }
    // The spot and point plan the last frame drew.
    const shadows::LocalShadowPlan& localPlan() const { return localPlan_; }
    // Point shadow cube maps (PointShadowMode::CubeMap; one unused cube otherwise).
    const shadows::ShadowCubes& shadowCubes() const { return *shadowCubes_; }
    // Why lights are drawn without shadows, or not at all (beyond maxLitDirectionalLights), and
    // why textures get less anisotropy than FrameDesc::maxAnisotropy.
    const std::vector<std::string>& notes() const { return notes_; }

    // Static shadow maps (ShadowSettings::staticMaps): the atlases as last drawn (16 texels wide without maps), and
    // the plan they were drawn from.
    const shadows::ShadowAtlas& staticDirectionalAtlas() const;
    // The static spot and point maps' atlas.
    const shadows::ShadowAtlas& staticLocalAtlas() const;
    // The plan the static maps were drawn from.
    const shadows::StaticShadowPlan& staticPlan() const;
    // In StaticShadowUpdate::OnDemand mode, the next render() draws every static map again from its plan; other modes
    // ignore it.
    void requestStaticShadowUpdate() { staticUpdateRequested_ = true; }
    // The static maps as the last render() left them, for a bake on disk (shadows::writeStaticShadowBake): light-space
    // depth that any configuration restores, with the hashes a later load checks. `configuration` is recorded.
    shadows::StaticShadowBake bakeStaticShadows(const std::string& configuration) const;
    // From now on the static maps come from `bake` and no static caster is drawn into them. render() then throws
    // rhi::Error, before drawing anything, when the frame's settings keep no static maps (staticMaps.update
    // everyFrame) or the bake does not hold the maps the scene and settings plan now (naming the light and what
    // differs).
    void useBakedShadows(shadows::StaticShadowBake bake);

    // The frame is a graph of passes (FramePass.hpp; FrameResources.hpp names the built-in passes and textures). An
    // application's pass runs before or after the built-in pass it names, every frame from the next render() on, and
    // reads and writes the frame's textures by name; several placed alike run in the order added. Throws rhi::Error
    // for a placement naming no built-in pass. The renderer keeps the pass.
    void addPass(std::shared_ptr<FramePass> pass, PassPlacement placement);
    // A texture of the application's that its passes use by `name`, one of the frame's outputs: the passes that lead
    // to it are never culled. It must outlive the renderer's frames.
    void addTexture(std::string name, const rhi::Texture& texture);
    // A buffer of the application's that its passes use by `name` (a storage buffer a compute pass fills and the
    // application reads after the frame's submission), one of the frame's outputs as addTexture's textures are. It
    // must outlive the renderer's frames.
    void addBuffer(std::string name, const rhi::Buffer& buffer);
    // The last frame's graph as Graphviz dot: its passes in order (culled ones and ones off that frame marked) and the
    // textures each reads and writes.
    std::string frameGraphDot() const;

    // For the negative control only (tests): false draws the shadow casters of skinned and morphed meshes from their
    // bind-pose vertices, as if the caster passes left skinning out, while every other pass draws the pose.
    void setCasterSkinning(bool on) { casterSkinning_ = on; }

private:
    void prepareTargets(const FrameDesc& frame, const ShadowPlans& plans);
    // What the frame's casters are made with: drawn from rest vertices without caster skinning, one draw each
    // without instancing (GpuScene::refresh).
    GpuScene::CasterOptions casterOptions(const FrameDesc& frame) const;
    // planShadows and render after GpuScene::refresh.
    ShadowPlans planRefreshed(const scene::Camera& camera, const FrameDesc& frame) const;
    FrameStats renderRefreshed(const scene::Camera& camera, const FrameDesc& frame, ShadowPlans plans);
    FrameStats prepareFrame(const scene::Camera& camera, const FrameDesc& frame, ShadowPlans& plans);
    std::vector<std::string> prepareStaticMaps(const FrameDesc& frame, shadows::StaticShadowPlan plan);
    std::vector<LitDraw> frameLitDraws(const scene::Camera& camera, const FrameDesc& frame, bool culledOnGpu);
    void fillFrameBlocks(const scene::Camera& camera, const FrameDesc& frame);
    rhi::BufferSlice localTileSlice();
    void importResources(const FrameDesc& frame);
    void buildGraph(const FrameDesc& frame);
    void readDepthHistogram();
    // The lit view's Frame block (the debug views change its view).
    LitFrameUniforms frameUniforms(const scene::Camera& camera, const FrameDesc& frame,
                                   const shadows::LightClusterUniforms& clusters) const;
    int litLightIndex(const scene::LightRef& light) const;

    rhi::Device& device_;
    GpuScene gpuScene_;
    // The directional planner's light-space caster boxes, kept from frame to frame (planning is const).
    mutable shadows::LightSpaceCache lightSpace_;
    std::unique_ptr<GpuSkinning> skinning_; // poses deformed meshes on the GPU (render/src/skinning)
    bool casterSkinning_ = true;
    shadows::DirectionalShadowPass shadowPass_;
    shadows::LocalShadowPass localShadowPass_;
    std::unique_ptr<LocalTileCache> localTiles_;
    std::unique_ptr<shadows::GpuCasterCulling> casterCulling_; // made on the first frame that culls on the GPU
    std::unique_ptr<rhi::Shader> litVertex_;
    // The shadow maps' set layout (ShadowMapBindings), which the lit and screen-space pipelines list.
    std::unique_ptr<rhi::BindingSetLayout> shadowMapLayout_;
    // Single-sampled: the lit pass without MSAA and the debug views. Multisampled: the lit pass with FrameDesc::msaa
    // samples, made when a frame first asks for that count.
    std::unique_ptr<LitPipelines> litPipelines_;
    std::unique_ptr<LitPipelines> multisampledLitPipelines_;
    std::unique_ptr<DepthPrepass> depthPrepass_; // with the lit pass's sample count
    // ShadowPath::ScreenSpace, made when a frame first asks for it: the single-sampled prepass with receivers (after
    // the multisampled depthPrepass_ with MSAA, instead of it without) and the collection.
    std::unique_ptr<DepthPrepass> receiverPrepass_;
    std::unique_ptr<ScreenSpaceShadowPass> screenSpace_;
    // Contact shadows and depth fit, made when a frame first asks for them: the march (with its own prepasses, which
    // write the view depth it reads), the reduction, and with MSAA on the forward path the single-sampled depth prepass
    // the reduction reads without contact shadows.
    std::unique_ptr<ContactShadowPass> contact_;
    std::unique_ptr<DepthReduction> depthReduction_;
    std::unique_ptr<DepthPrepass> singleSampledPrepass_;
    std::optional<shadows::DepthHistogram> depthHistogram_;
    std::unique_ptr<StaticShadowCache> staticShadows_;
    std::unique_ptr<EnvironmentMaps> environment_; // FrameDesc::environment prefiltered
    std::unique_ptr<LocalLightTextures> localLights_; // every spot and point light and their cluster lists
    // RealtimeCasters::Dynamic: the static casters' depth of the realtime atlases' tiles.
    std::unique_ptr<StaticTileCache> directionalStaticTiles_;
    std::unique_ptr<StaticTileCache> localStaticTiles_;
    bool staticUpdateRequested_ = false;
    // This frame's draws (passes/LitDraws.hpp), shared by the prepass and every lit view.
    std::vector<LitDraw> litDraws_;
    std::unique_ptr<GpuViewCulling> viewCulling_; // made on the first frame that culls on the GPU, with instancing
    std::unique_ptr<rhi::CommandList> commands_;
    std::unique_ptr<FrameGraph> graph_;
    std::unique_ptr<FrameState> state_; // what this frame's passes draw
    std::unique_ptr<rhi::BindingSet> shadowMapSet_; // this frame's (FrameState::shadowMapSet)
    std::vector<std::unique_ptr<FramePass>> framePasses_; // this frame's built-in passes
    std::unique_ptr<ApplicationPasses> applicationPasses_; // addPass, addTexture, addBuffer
    rhi::UniformArena uniforms_;
    rhi::VertexArena instances_; // the lit draws' instance transforms
    rhi::BufferArena storage_; // the local atlas's tiles (shadows::LocalAtlasTileData), read by the lit shaders

    std::unique_ptr<shadows::ShadowAtlas> atlas_;
    std::unique_ptr<shadows::ShadowAtlas> localAtlas_;
    std::unique_ptr<shadows::ShadowCubes> shadowCubes_;
    std::unique_ptr<rhi::Texture> lit_;
    std::unique_ptr<rhi::Texture> cascades_;
    std::unique_ptr<rhi::Texture> depth_;
    std::unique_ptr<rhi::Texture> visibility_;

    shadows::DirectionalShadowPlan plan_;
    shadows::LocalShadowPlan localPlan_;
    std::vector<std::string> notes_;
};

} // namespace penumbra::render
