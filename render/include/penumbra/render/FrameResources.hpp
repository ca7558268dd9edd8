#pragma once

#include <array>
#include <string_view>

// The names of the frame's built-in passes, textures and buffers, as SceneRenderer's graph knows them: what a user's
// pass reads or writes (FramePassBuilder) and where it is placed (PassPlacement). `penumbra render --graph` draws them.
namespace penumbra::render::frame {

// Passes, in the order they run.
inline constexpr std::string_view kSkinningPass = "skinning"; // a scene with skinned or morphed meshes
inline constexpr std::string_view kStaticMapsPass = "static maps";
// Shadow casters culled per tile on the GPU (ShadowSettings::culling gpu).
inline constexpr std::string_view kCasterCullingPass = "caster culling";
// The opaque lit objects culled against the camera's view on the GPU (ShadowSettings::culling gpu, with instancing).
inline constexpr std::string_view kViewCullingPass = "view culling";
// The clustered light lists built on the GPU (ShadowSettings local.clusterBuild gpu).
inline constexpr std::string_view kLightClusterPass = "light cluster build";
inline constexpr std::string_view kDirectionalStaticTilesPass = "directional static tiles";
inline constexpr std::string_view kDirectionalAtlasPass = "directional atlas";
inline constexpr std::string_view kLocalStaticTilesPass = "local static tiles";
inline constexpr std::string_view kLocalAtlasPass = "local atlas";
inline constexpr std::string_view kDepthPrepass = "depth prepass";
inline constexpr std::string_view kSingleSampledDepthPrepass = "single-sampled depth prepass";
inline constexpr std::string_view kReceiverPrepass = "receiver prepass";
inline constexpr std::string_view kScreenSpaceShadowsPass = "screen-space shadows";
inline constexpr std::string_view kContactShadowsPass = "contact shadows";
inline constexpr std::string_view kLitPass = "lit";
inline constexpr std::string_view kDepthReductionPass = "depth reduction";
inline constexpr std::string_view kResolvePass = "msaa resolve";
inline constexpr std::string_view kCascadeViewPass = "cascade view";
inline constexpr std::string_view kVisibilityViewPass = "visibility view";
inline constexpr std::array kPasses{kSkinningPass,
                                    kStaticMapsPass,
                                    kCasterCullingPass,
                                    kViewCullingPass,
                                    kLightClusterPass,
                                    kDirectionalStaticTilesPass,
                                    kDirectionalAtlasPass,
                                    kLocalStaticTilesPass,
                                    kLocalAtlasPass,
                                    kDepthPrepass,
                                    kSingleSampledDepthPrepass,
                                    kReceiverPrepass,
                                    kScreenSpaceShadowsPass,
                                    kContactShadowsPass,
                                    kLitPass,
                                    kDepthReductionPass,
                                    kResolvePass,
                                    kCascadeViewPass,
                                    kVisibilityViewPass};

// Textures. The lit image, the atlases and the views are the frame's outputs (SceneRenderer's accessors read them).
inline constexpr std::string_view kLitImage = "lit image"; // RGBA8 sRGB-encoded, single-sampled
inline constexpr std::string_view kLitDepth = "lit depth"; // single-sampled, sampled: the prepass's depth
inline constexpr std::string_view kMultisampledColor = "lit image (multisampled)"; // FrameDesc::msaa > 1
inline constexpr std::string_view kMultisampledDepth = "lit depth (multisampled)"; // FrameDesc::msaa > 1
inline constexpr std::string_view kDirectionalAtlas = "directional atlas";
inline constexpr std::string_view kLocalAtlas = "local atlas";
inline constexpr std::string_view kShadowCubes = "shadow cubes";
inline constexpr std::string_view kStaticDirectionalAtlas = "static directional atlas";
inline constexpr std::string_view kStaticLocalAtlas = "static local atlas";
// Every spot and point light and their clustered lists (LitUniforms.hpp's data textures), written on the CPU; the
// lists by the light cluster build pass with local.clusterBuild gpu.
inline constexpr std::string_view kLocalLights = "local lights";
inline constexpr std::string_view kLightClusters = "light clusters";
inline constexpr std::string_view kLightIndices = "light indices";
// The screen-space path's receiver prepass: the world position's screen derivatives.
inline constexpr std::string_view kReceiverPositionDx = "receiver position dx";
inline constexpr std::string_view kReceiverPositionDy = "receiver position dy";
inline constexpr std::string_view kScreenSpaceShadows = "screen-space shadows";
// shadows.contact: each directional light's contact shadow march (render/src/passes/ContactShadowPass).
inline constexpr std::string_view kContactShadows = "contact shadows";
// shadows.contact: the view depth the prepass writes beside the lit depth, which the march reads (view_depth.glsl).
inline constexpr std::string_view kContactViewDepth = "contact view depth";
inline constexpr std::string_view kCascadeView = "cascade view";
inline constexpr std::string_view kVisibilityView = "visibility view";

// Buffers that passes write and later passes read within the frame.
// The deformed meshes' vertex buffers, posed by the skinning pass and drawn by every pass that draws the scene (a
// scene with skinned or morphed meshes).
inline constexpr std::string_view kPosedVertices = "posed vertices";
// ShadowSettings::culling gpu: the caster culling pass's per-tile instance lists (per-instance vertices) and indexed
// indirect draws with their counts, which the atlas passes draw.
inline constexpr std::string_view kCulledInstances = "culled instances";
inline constexpr std::string_view kCulledDraws = "culled draws";
// The same of the view culling pass, which the depth prepasses and the lit passes draw.
inline constexpr std::string_view kViewCulledInstances = "view-culled instances";
inline constexpr std::string_view kViewCulledDraws = "view-culled draws";
// directional.projection depthFit: the depth reduction's histogram, an output the renderer reads after the frame.
inline constexpr std::string_view kDepthHistogram = "depth histogram";

} // namespace penumbra::render::frame
