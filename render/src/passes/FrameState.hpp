#pragma once

#include "LitDraws.hpp"

#include "penumbra/render/FramePass.hpp"
#include "penumbra/render/FrameResources.hpp"
#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/shadows/GpuCasterCulling.hpp"
#include "penumbra/shadows/ShadowCaster.hpp"

#include <memory>
#include <span>
#include <vector>

namespace penumbra::render {

class ContactShadowPass;
class EnvironmentMaps;
class LocalLightTextures;
class StaticShadowCache;

// The lit pass's shadow bindings (atlases, cubes, their blocks, static maps), which the screen-space collection and
// the debug views share, bound with one binding set per pass.
struct ShadowMapBindings {
    shadows::ShadowAtlas* directional = nullptr;
    shadows::ShadowAtlas* local = nullptr;
    const shadows::ShadowCubes* cubes = nullptr;
    const StaticShadowCache* staticMaps = nullptr;
    rhi::UniformSlice directionalUniforms;
    rhi::UniformSlice localUniforms;
    rhi::UniformSlice staticUniforms;
    rhi::BufferSlice localTiles; // the storage block LocalShadowTiles

    // The layout of their set: the lit shaders' binding numbers.
    static rhi::BindingSetLayoutDesc layoutDesc();
    // This frame's set of them (the blocks move every frame), against a layout made from layoutDesc().
    std::unique_ptr<rhi::BindingSet> createSet(rhi::Device& device, const rhi::BindingSetLayout& layout) const;
};

// Declares the reads of every texture ShadowMapBindings binds.
void readShadowMaps(FramePassBuilder& builder);
// Declares the reads of the local light textures (LocalLightTextures).
void readLocalLights(FramePassBuilder& builder);

struct FrameState;
// For a pass that draws the scene's meshes: declares the posed vertices' read where the frame has them.
void readPosedVertices(FramePassBuilder& builder, const FrameState& state);
// The buffers a GPU culling pass writes and later passes draw: per-instance vertices, and indexed indirect draws with
// their counts.
struct CulledBuffers {
    std::string_view instances;
    std::string_view draws;
};
inline constexpr CulledBuffers kCulledCasters{frame::kCulledInstances, frame::kCulledDraws};
inline constexpr CulledBuffers kViewCulled{frame::kViewCulledInstances, frame::kViewCulledDraws};

// For an atlas pass: declares the caster culling pass's results' reads where the frame culls on the GPU.
void readCulledCasters(FramePassBuilder& builder, const FrameState& state);
// For a pass that draws the lit draws (FrameState::litDraws): readPosedVertices, and the view culling pass's results'
// reads where the frame culls the view on the GPU.
void readLitDraws(FramePassBuilder& builder, const FrameState& state);

// RealtimeCasters::Dynamic: the tiles' static casters, which the realtime atlases take from StaticTileCache, and
// the tiles without them, which the passes draw over it.
struct SplitTiles {
    std::vector<shadows::ShadowTileDraw> directional;
    std::vector<shadows::ShadowTileDraw> local;
};

// Moves the static casters (`staticCasters`, sorted) out of the plans' tiles into the returned tiles.
SplitTiles splitStaticCasters(ShadowPlans& plans, const std::vector<std::uint32_t>& staticCasters);

// What SceneRenderer planned for this frame and its built-in passes draw: set before the graph compiles, read by the
// passes' setup and execute, which add their counts to `stats`.
struct FrameState {
    const FrameDesc* desc = nullptr;
    FrameStats* stats = nullptr;
    std::span<const shadows::ShadowCaster> casters;
    std::span<const LitDraw> litDraws;
    ShadowMapBindings shadowMaps;
    const rhi::BindingSet* shadowMapSet = nullptr; // shadowMaps' set, bound once by each pass that reads them
    const EnvironmentMaps* environment = nullptr; // the lit pass's image-based lighting textures
    const LocalLightTextures* localLights = nullptr; // the lit pass's and its views' spot and point lights
    LocalLightTextures* gpuClusters = nullptr; // local.clusterBuild gpu: the lists the light cluster pass builds
    SplitTiles staticTiles; // empty unless the realtime atlases draw dynamic casters only
    // ShadowSettings::culling gpu (culledOnGpu): the culling pass's results, which the atlas passes draw; the local
    // atlas's tiles follow the directional ones, from culledLocalTile.
    shadows::GpuCasterCulling* culling = nullptr;
    std::uint32_t culledLocalTile = 0;
    // ShadowSettings::culling gpu with instancing: the view culling pass's results, which the opaque lit draws draw.
    shadows::GpuCasterCulling* viewCulling = nullptr;
    bool posedVertices = false; // the scene has deformed meshes, which the skinning pass poses (kPosedVertices)
    bool screenSpace = false; // directional shadows collected in screen space
    bool multisampled = false;
    bool depthFit = false; // directional.projection depthFit: the lit depth is reduced for the next frame's plan
    bool contact = false; // shadows.contact: the lit pass takes the contact shadow texture's minimum
    const ContactShadowPass* contactShadows = nullptr; // its texture, with `contact`
    rhi::UniformSlice contactUniforms; // the contact march's block (ContactShadowUniforms)
    std::vector<glm::vec3> depthFitLights; // depth fit: the plan's shadowed directional lights, in slot order
    float depthFitShadowFar = 0.0f; // depth fit: min(shadow distance, camera far), where the histogram ends
    rhi::UniformArena* uniforms = nullptr; // this frame's blocks
    LitFrameUniforms litFrameUniforms; // the lit view's Frame block
    rhi::UniformSlice litFrame; // litFrameUniforms, pushed
    int visibilityLight = -1; // the visibility view's light, in the lit pass's order (FrameDesc::visibilityOf)
    // The features the frame's lights and shadow maps need (frameShaderFeatures): forward shadows, no prepass.
    LitShaderFeatures features;
};

} // namespace penumbra::render
