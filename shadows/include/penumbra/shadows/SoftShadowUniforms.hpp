#pragma once

#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>

namespace penumbra::shadows {

// SoftShadowSettings as the lit shader's blocks carry them: the GLSL struct SoftControls (soft_shadows.glsl).
struct alignas(16) SoftShadowUniforms {
    float searchScale = 0.0f; // SoftShadowSettings::blockerSearchScale
    float penumbraScale = 0.0f;
    float minTexels = 0.0f; // the penumbra's clamp, in texels
    float maxTexels = 0.0f;
    std::int32_t blockerSamples = 0;
    std::int32_t filterSamples = 0;
    float poissonRadius = 0.0f; // texels
    std::int32_t diskRotation = 0; // 1: the disk turns per receiver texel (SoftShadowSettings::diskRotation)
};

inline constexpr std::array kSoftShadowFields{
    PENUMBRA_SHADER_FIELD(SoftShadowUniforms, searchScale),    PENUMBRA_SHADER_FIELD(SoftShadowUniforms, penumbraScale),
    PENUMBRA_SHADER_FIELD(SoftShadowUniforms, minTexels),      PENUMBRA_SHADER_FIELD(SoftShadowUniforms, maxTexels),
    PENUMBRA_SHADER_FIELD(SoftShadowUniforms, blockerSamples), PENUMBRA_SHADER_FIELD(SoftShadowUniforms, filterSamples),
    PENUMBRA_SHADER_FIELD(SoftShadowUniforms, poissonRadius),  PENUMBRA_SHADER_FIELD(SoftShadowUniforms, diskRotation),
};
inline constexpr shaders::ShaderStruct kSoftShadowStruct{"SoftControls", sizeof(SoftShadowUniforms), kSoftShadowFields};
static_assert(shaders::matchesLayout(kSoftShadowStruct, shaders::BlockLayout::Std140, true));

// What the Poisson and PCSS filters (soft_shadows.glsl) need of a directional tile, the realtime cascades'
// (DirectionalShadowUniforms::tileSoft) and the static maps' (StaticShadowUniforms::directionalSoft) alike: the GLSL
// struct DirectionalTileSoft, made by directionalTileSoft (DirectionalSoftData.hpp).
struct alignas(16) DirectionalTileSoft {
    glm::vec2 lightTexelAnchor{0.0f}; // added to a tile texel, the light-space texel (the disk's rotation)
    // The depth row: orthographicDistanceFromNear gives the distance past the nearest caster's light-space depth.
    glm::vec2 depthRow{0.0f};
};

inline constexpr std::array kDirectionalTileSoftFields{
    PENUMBRA_SHADER_FIELD(DirectionalTileSoft, lightTexelAnchor),
    PENUMBRA_SHADER_FIELD(DirectionalTileSoft, depthRow),
};
inline constexpr shaders::ShaderStruct kDirectionalTileSoftStruct{"DirectionalTileSoft", sizeof(DirectionalTileSoft),
                                                                  kDirectionalTileSoftFields};
static_assert(shaders::matchesLayout(kDirectionalTileSoftStruct, shaders::BlockLayout::Std140, true));

// What the Poisson and PCSS filters need of a perspective (spot or point) tile: the GLSL struct PerspectiveTileSoft,
// made by perspectiveTileSoft (LocalLightProjection.hpp).
struct alignas(16) PerspectiveTileSoft {
    glm::vec2 depthRow{0.0f}; // (t22, t32) of clipToTexture x projection: perspectiveDistance
    float lightTexels = 0.0f; // the light's radius in texels at unit distance
    float nearPlane = 0.0f;
};

inline constexpr std::array kPerspectiveTileSoftFields{
    PENUMBRA_SHADER_FIELD(PerspectiveTileSoft, depthRow),
    PENUMBRA_SHADER_FIELD(PerspectiveTileSoft, lightTexels),
    PENUMBRA_SHADER_FIELD(PerspectiveTileSoft, nearPlane),
};
inline constexpr shaders::ShaderStruct kPerspectiveTileSoftStruct{"PerspectiveTileSoft", sizeof(PerspectiveTileSoft),
                                                                  kPerspectiveTileSoftFields};
static_assert(shaders::matchesLayout(kPerspectiveTileSoftStruct, shaders::BlockLayout::Std140, true));

SoftShadowUniforms softShadowUniforms(const SoftShadowSettings& soft);

// tan of half a directional light's angular diameter (degrees).
float tanHalfAngularDiameter(float degrees);

} // namespace penumbra::shadows
