#pragma once

#include "penumbra/rhi/Format.hpp"
#include "penumbra/rhi/Shader.hpp"
#include "penumbra/scene/Material.hpp"
#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shadows/LightClusters.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string_view>

namespace penumbra::render {

inline constexpr std::uint32_t maxLitDirectionalLights = 8;
// The screen-space shadow texture's channels: directional lights 0 to 3 (FrameDesc::shadowPath).
inline constexpr std::uint32_t maxCollectedDirectionalLights = 4;

// The lit pass's colour (SceneRenderer::litImage(), sRGB-encoded by the shader) and depth formats; with
// FrameDesc::msaa above 1 both are multisampled, so the device must offer that count for both.
inline constexpr rhi::Format kLitColorFormat = rhi::Format::RGBA8;
inline constexpr rhi::Format kLitDepthFormat = rhi::Format::D32F;

// What the lit pass writes: the lit image, the lit image tinted by cascade, or one light's raw shadow-map
// visibility (FrameDesc::visibilityOf).
enum class LitView : std::int32_t { Lit = 0, Cascades = 1, Visibility = 2 };

// One directional light as the lit pass and the screen-space collection see it.
struct alignas(16) LitDirectionalLight {
    alignas(16) glm::vec3 color{0.0f}; // linear rgb x intensity
    std::int32_t shadowSlot = -1; // its DirectionalShadowUniforms::lights entry, -1 without realtime shadows
    alignas(16) glm::vec3 direction{0.0f}; // unit, from the light into the scene
};

inline constexpr std::array kLitDirectionalLightFields{
    PENUMBRA_SHADER_FIELD(LitDirectionalLight, color),
    PENUMBRA_SHADER_FIELD(LitDirectionalLight, shadowSlot),
    PENUMBRA_SHADER_FIELD(LitDirectionalLight, direction),
};
inline constexpr shaders::ShaderStruct kLitDirectionalLightStruct{"DirectionalLight", sizeof(LitDirectionalLight),
                                                                  kLitDirectionalLightFields};

// The blocks of shaders/lit.glsl (kLitFrameBlock, kLitObjectBlock below), uploaded as they are.
struct LitFrameUniforms {
    glm::mat4 viewProjection{1.0f};
    glm::vec4 cameraPosition{0.0f};
    glm::vec4 cameraForward{0.0f};
    std::array<LitDirectionalLight, maxLitDirectionalLights> lights{};
    glm::vec4 ambient{0.0f};
    std::int32_t directionalLightCount = 0;
    std::int32_t litView = 0; // LitView
    std::int32_t localLightCount = 0;
    std::int32_t visibilityLight = 0; // LitView::Visibility's light: directional lights first, then spot and point
    // The camera's view frame as shadows::buildLightClusters cuts it into clusters: its x and y axes (unit, world
    // space), each with the tangent of the half field of view along it, and the slices' near and far planes, scale
    // and bias (shadows::LightClusterUniforms).
    alignas(16) glm::vec3 cameraRight{0.0f};
    float tanHalfFovX = 0.0f;
    alignas(16) glm::vec3 cameraUp{0.0f};
    float tanHalfFovY = 0.0f;
    float clusterNear = 0.0f;
    float clusterFar = 0.0f;
    float clusterSliceScale = 0.0f;
    float clusterSliceBias = 0.0f;
    glm::vec4 ambientGround{0.0f}; // linear rgb from below (the hemisphere's ground; = ambient without one)
    // Image-based lighting (shaders/environment_light.glsl): the cosine and sine of the rotation about +y, the
    // specular chain's last level (0: no environment, the ambient light instead), the intensity; and the diffuse
    // coefficients (diffuseShaderCoefficients, at intensity 1).
    float environmentCos = 0.0f;
    float environmentSin = 0.0f;
    float environmentLastLevel = 0.0f;
    float environmentIntensity = 0.0f;
    std::array<glm::vec4, 9> environmentSh{};
};

// The lit pass's spot and point lights (spot lights, then point lights: the lit pass's local index) and their
// clustered lists (shadows::buildLightClusters with kLitClusterGrid), in data textures that lit.frag reads with
// texelFetch, uploaded by the CPU or, for the lists, written as storage images by the light cluster pass
// (local.clusterBuild). Each texture is kLitDataTextureWidth texels wide with as many rows
// as the frame needs, rounded up to a power of two; texel t of a texture lies at column t % width, row t / width.
inline constexpr std::uint32_t kLitDataTextureWidthLog2 = 10;
inline constexpr std::uint32_t kLitDataTextureWidth = 1u << kLitDataTextureWidthLog2;
inline constexpr shadows::LightClusterGridDesc kLitClusterGrid{};
// One spot or point light in the local light texture: local light i takes texels i * kLocalLightTexels onwards.
// lit.frag reads each field through the accessor generated from kLocalLightRecord (shaders::texelRecordGlsl:
// localLightPosition(i), localLightColor(i)...). Integers are stored as floats (exact up to 2^24).
struct LocalLightRecord {
    glm::vec3 position{0.0f};
    float inverseRangeSquared = 0.0f; // 1 / range^2
    glm::vec3 color{0.0f}; // linear rgb x intensity
    float kind = 0.0f; // scene::LightKind
    glm::vec3 axis{0.0f}; // spot cone axis (unit, away from the light); 0 for a point light
    float contactBit = -1.0f; // its bit in the contact shadow texture (contactLocalLights) or -1
    float coneScale = 0.0f; // the spot cone's smooth step: saturate(cos * coneScale + coneOffset); 0 for a point light
    float coneOffset = 0.0f;
    float shadowTile = 0.0f; // first shadow tile (LocalShadowPlan::spotTiles, pointShadows) or -1
    float shadowStrength = 0.0f;
    float staticTile = -1.0f; // first tile of its static map or -1 (shadows::StaticShadowPlan::localLightMaps)
    float staticStrength = 0.0f; // that map's strength
    glm::vec2 staticPadding{0.0f};
};
inline constexpr std::array kLocalLightRecordFields{
    PENUMBRA_SHADER_FIELD(LocalLightRecord, position),   PENUMBRA_SHADER_FIELD(LocalLightRecord, inverseRangeSquared),
    PENUMBRA_SHADER_FIELD(LocalLightRecord, color),      PENUMBRA_SHADER_FIELD(LocalLightRecord, kind),
    PENUMBRA_SHADER_FIELD(LocalLightRecord, axis),       PENUMBRA_SHADER_FIELD(LocalLightRecord, contactBit),
    PENUMBRA_SHADER_FIELD(LocalLightRecord, coneScale),  PENUMBRA_SHADER_FIELD(LocalLightRecord, coneOffset),
    PENUMBRA_SHADER_FIELD(LocalLightRecord, shadowTile), PENUMBRA_SHADER_FIELD(LocalLightRecord, shadowStrength),
    PENUMBRA_SHADER_FIELD(LocalLightRecord, staticTile), PENUMBRA_SHADER_FIELD(LocalLightRecord, staticStrength),
};
inline constexpr shaders::ShaderStruct kLocalLightRecord{"LocalLightRecord", sizeof(LocalLightRecord),
                                                         kLocalLightRecordFields};
static_assert(shaders::fitsTexels(kLocalLightRecord));
inline constexpr std::uint32_t kLocalLightTexels = sizeof(LocalLightRecord) / 16;
inline constexpr rhi::Format kLocalLightFormat = rhi::Format::RGBA32F;
// Texel c of the cluster texture is cluster c's list: x = its first entry in the index texture, y = its length.
inline constexpr rhi::Format kLightClusterFormat = rhi::Format::RGBA32F;
// The clusters' lists one after another, a local light index per texel (exact in a float up to 2^24).
inline constexpr rhi::Format kLightIndexFormat = rhi::Format::R32F;

// What the instances of one lit draw share; their transforms are per instance (shadows::InstanceTransform).
struct LitObjectUniforms {
    glm::vec4 baseColor{1.0f};
    float metallic = 0.0f;
    float roughness = 0.0f;
    float alphaCutoff = 0.0f;
    std::int32_t casterMode = 0; // scene::CasterMode, compared with PENUMBRA_CASTER_* (material.glsl)
    std::int32_t receivesShadows = 0;
    std::int32_t materialMaps = 0; // textures present, bit per scene::TextureSlot
    std::int32_t unlit = 0;
    std::int32_t blended = 0;
    alignas(16) glm::vec3 emissive{0.0f}; // linear rgb
    float occlusionStrength = 0.0f;
    float normalScale = 0.0f; // the normal texture's scale
    // Per scene::TextureSlot, rows 0 and 1 of its uv transform, row 0's w its uv set (shadows::uvTransformRows).
    alignas(16) std::array<glm::vec4, 2 * scene::kTextureSlots> uvTransforms{};
};

inline constexpr std::array kLitFrameFields{
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, viewProjection),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, cameraPosition),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, cameraForward),
    PENUMBRA_SHADER_STRUCT_FIELD(LitFrameUniforms, lights, kLitDirectionalLightStruct),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, ambient),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, directionalLightCount),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, litView),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, localLightCount),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, visibilityLight),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, cameraRight),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, tanHalfFovX),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, cameraUp),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, tanHalfFovY),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, clusterNear),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, clusterFar),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, clusterSliceScale),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, clusterSliceBias),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, ambientGround),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, environmentCos),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, environmentSin),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, environmentLastLevel),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, environmentIntensity),
    PENUMBRA_SHADER_FIELD(LitFrameUniforms, environmentSh),
};
// lit.glsl's block Frame, read through the instance name `frame`.
inline constexpr shaders::ShaderStruct kLitFrameBlock{"Frame", sizeof(LitFrameUniforms), kLitFrameFields};
static_assert(shaders::matchesLayout(kLitFrameBlock, shaders::BlockLayout::Std140));

inline constexpr std::array kLitObjectFields{
    PENUMBRA_SHADER_FIELD(LitObjectUniforms, baseColor),
    PENUMBRA_SHADER_FIELD(LitObjectUniforms, metallic),
    PENUMBRA_SHADER_FIELD(LitObjectUniforms, roughness),
    PENUMBRA_SHADER_FIELD(LitObjectUniforms, alphaCutoff),
    PENUMBRA_SHADER_FIELD(LitObjectUniforms, casterMode),
    PENUMBRA_SHADER_FIELD(LitObjectUniforms, receivesShadows),
    PENUMBRA_SHADER_FIELD(LitObjectUniforms, materialMaps),
    PENUMBRA_SHADER_FIELD(LitObjectUniforms, unlit),
    PENUMBRA_SHADER_FIELD(LitObjectUniforms, blended),
    PENUMBRA_SHADER_FIELD(LitObjectUniforms, emissive),
    PENUMBRA_SHADER_FIELD(LitObjectUniforms, occlusionStrength),
    PENUMBRA_SHADER_FIELD(LitObjectUniforms, normalScale),
    PENUMBRA_SHADER_FIELD(LitObjectUniforms, uvTransforms),
};
// lit.glsl's block Object, read through the instance name `object`.
inline constexpr shaders::ShaderStruct kLitObjectBlock{"Object", sizeof(LitObjectUniforms), kLitObjectFields};
static_assert(shaders::matchesLayout(kLitObjectBlock, shaders::BlockLayout::Std140));

// Bindings of the lit pass; material textures take kLitMaterialMapBinding + scene::TextureSlot.
inline constexpr std::uint32_t kLitFrameBinding = 0;
inline constexpr std::uint32_t kLitObjectBinding = 1;
inline constexpr std::uint32_t kLitShadowBinding = 2;
inline constexpr std::uint32_t kLitAtlasBinding = 3;
inline constexpr std::uint32_t kLitLocalShadowBinding = 4;
inline constexpr std::uint32_t kLitLocalAtlasBinding = 5;
inline constexpr std::uint32_t kLitShadowCubesBinding = 6;
// The same cube array read raw (no comparison): the soft filters' blocker search.
inline constexpr std::uint32_t kLitShadowCubeDepthsBinding = 7;
inline constexpr std::uint32_t kLitMaterialMapBinding = 8;
// After the material maps: the static shadow maps (shadows::StaticShadowUniforms and its two atlases).
inline constexpr std::uint32_t kLitStaticShadowBinding = kLitMaterialMapBinding + scene::kTextureSlots;
inline constexpr std::uint32_t kLitStaticDirectionalAtlasBinding = kLitStaticShadowBinding + 1;
inline constexpr std::uint32_t kLitStaticLocalAtlasBinding = kLitStaticShadowBinding + 2;
// The base colour map again, through GpuScene::coverageSampler: the alpha every pass cuts and blends by.
inline constexpr std::uint32_t kLitCoverageMapBinding = kLitStaticShadowBinding + 3;
// The screen-space shadow texture (DirectionalShadowSource::ScreenSpace), and with ScreenSpaceEdges the single-sampled
// depth it was collected from.
inline constexpr std::uint32_t kLitScreenSpaceShadowsBinding = kLitCoverageMapBinding + 1;
inline constexpr std::uint32_t kLitScreenSpaceDepthBinding = kLitCoverageMapBinding + 2;
// The local light, cluster and light index textures (kLocalLightFormat and after).
inline constexpr std::uint32_t kLitLocalLightsBinding = kLitScreenSpaceDepthBinding + 1;
inline constexpr std::uint32_t kLitLightClustersBinding = kLitScreenSpaceDepthBinding + 2;
inline constexpr std::uint32_t kLitLightIndicesBinding = kLitScreenSpaceDepthBinding + 3;
// The realtime local atlas's tiles (the storage block LocalShadowTiles, shadows::LocalAtlasTileData per tile). The
// screen-space collection binds it too, beside its own bindings 1 to 4 after kLitScreenSpaceDepthBinding
// (ScreenSpaceShadowPass.hpp).
inline constexpr std::uint32_t kLitLocalShadowTilesBinding = kLitScreenSpaceDepthBinding + 5;
// The environment's prefiltered specular chain and the split-sum BRDF table (render/src/EnvironmentMaps.hpp).
inline constexpr std::uint32_t kLitEnvironmentSpecularBinding = kLitLocalShadowTilesBinding + 1;
inline constexpr std::uint32_t kLitEnvironmentBrdfBinding = kLitLocalShadowTilesBinding + 2;
// The contact shadow texture (LitShaderFeatures::contactShadows; render/src/passes/ContactShadowPass.hpp).
inline constexpr std::uint32_t kLitContactShadowsBinding = kLitEnvironmentBrdfBinding + 1;

inline constexpr std::uint32_t litMaterialMapBinding(scene::TextureSlot slot)
{
    return kLitMaterialMapBinding + static_cast<std::uint32_t>(slot);
}

// Where the lit shader's directional shadows come from (FrameDesc::shadowPath). Forward: evaluated per fragment.
// ScreenSpace: read at the fragment's pixel from the screen-space shadow texture (ScreenSpaceShadowPass), which
// holds each of the first maxCollectedDirectionalLights lights' attenuation for the surface the depth prepass left
// there. ScreenSpaceEdges (multisampled lit pass): read where the fragment covers every sample of its pixel and the
// collection's depth is its own, evaluated forward elsewhere, so edge pixels do not take the surface behind's shadow.
enum class DirectionalShadowSource : std::uint8_t { Forward = 0, ScreenSpace = 1, ScreenSpaceEdges = 2 };

// Which parts of the lit shader are compiled in. Mesa's llvmpipe and lavapipe run both sides of every branch under
// an execution mask and every loop body at least once, whatever the uniforms say (Mesa,
// src/gallium/auxiliary/gallivm/lp_bld_nir_soa.c: if_cond, endloop), so a part that neither the frame nor the
// material can use is left out of the shader instead of skipped at run time. The default compiles everything in.
struct LitShaderFeatures {
    bool depthPrepassed = false; // after a depth prepass: an equal depth test instead of lit.frag's alpha discard
    LitView view = LitView::Lit;
    // The material maps lit.frag may read (bit per scene::TextureSlot, as LitObjectUniforms::materialMaps); a map
    // outside it reads as the white texel that stands in for an absent map.
    std::uint32_t materialMaps = (1u << scene::kTextureSlots) - 1;
    bool localLights = true; // spot and point lights
    bool staticShadows = true; // static shadow maps (shadows::StaticShadowUniforms)
    bool tentFilters = true; // PCF 3x3, 5x5, 7x7 (PCF 2x2 is always compiled in)
    bool softFilters = true; // Poisson and PCSS
    bool shadowCubes = true; // point lights' shadows in cube maps (shadows::PointShadowMode::CubeMap)
    DirectionalShadowSource directionalShadows = DirectionalShadowSource::Forward;
    // The lit pass's samples per pixel (FrameDesc::msaa; LitPipelines sets it): ScreenSpaceEdges tells a fragment
    // that covers its whole pixel by it.
    std::uint32_t samples = 1;
    // Each directional light's direct term takes the minimum with its contact shadow (shadows.contact), upsampled
    // at the fragment's pixel from the half-resolution march; with MSAA only where the fragment is the pixel's
    // single-sampled surface. Off by default: the frame binds the contact shadow texture only when it draws them.
    bool contactShadows = false;

    // Equal features compile to the same lit shader variant.
    bool operator==(const LitShaderFeatures&) const = default;
};

// The material maps a material has, bit per scene::TextureSlot (LitObjectUniforms::materialMaps).
std::uint32_t litMaterialMaps(const scene::Material& material);

// The lit pass shader `fileName` ("lit.vert", "lit.frag") with the includes "lit_constants.glsl" that lit.glsl reads
// (the material texture bindings and TextureSlot numbers above as GLSL macros, so the numbers are written once,
// here, and `features` as PENUMBRA_DEPTH_PREPASSED, PENUMBRA_LIT_VIEW, PENUMBRA_LIT_MAPS, PENUMBRA_LOCAL_LIGHTS,
// PENUMBRA_STATIC_SHADOWS and PENUMBRA_SCREEN_SPACE_SHADOWS) and "shadow_constants.glsl" (the filters, with
// PENUMBRA_TENT_FILTERS, PENUMBRA_SOFT_FILTERS and PENUMBRA_SHADOW_CUBES).
rhi::ShaderSource litShader(std::string_view fileName, const LitShaderFeatures& features = {});

} // namespace penumbra::render
