#pragma once

#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shadows/CascadeData.hpp"
#include "penumbra/shadows/ShadowFade.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"
#include "penumbra/shadows/SoftShadowUniforms.hpp"
#include "penumbra/shadows/TileTexelBounds.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace penumbra::shadows {

inline constexpr std::uint32_t maxShadowedDirectionalLights = 4;
inline constexpr std::uint32_t maxCascades = 4;

// What the lit shader knows of one shadowed directional light (its shadow slot).
struct alignas(16) DirectionalShadowLight {
    float strength = 0.0f;
    float normalBias = 0.0f; // the receiver-side normal offset, 0 where the caster side takes it
    std::int32_t firstTile = 0; // its first cascade's atlas tile; cascade c is firstTile + c
    ShadowFilter shadowFilter = ShadowFilter::PCF2x2;
    float tanHalfAngle = 0.0f; // tan of half the light's angular diameter (the Poisson and PCSS filters)
    float filterBiasScale = 0.0f; // normalBiasFilterFactor of the light's filter over the atlas's
};

inline constexpr std::array kDirectionalShadowLightFields{
    PENUMBRA_SHADER_FIELD(DirectionalShadowLight, strength),
    PENUMBRA_SHADER_FIELD(DirectionalShadowLight, normalBias),
    PENUMBRA_SHADER_FIELD(DirectionalShadowLight, firstTile),
    PENUMBRA_SHADER_FIELD(DirectionalShadowLight, shadowFilter),
    PENUMBRA_SHADER_FIELD(DirectionalShadowLight, tanHalfAngle),
    PENUMBRA_SHADER_FIELD(DirectionalShadowLight, filterBiasScale),
};
inline constexpr shaders::ShaderStruct kDirectionalShadowLightStruct{"DirectionalShadowLight",
                                                                     sizeof(DirectionalShadowLight),
                                                                     kDirectionalShadowLightFields};

// The lit shader's directional-shadow uniform block DirectionalShadows (directional_shadows.glsl), uploaded as is.
struct DirectionalShadowUniforms {
    // Per tile (light * cascadeCount + cascade): world -> (u, v, depth) in the atlas.
    std::array<glm::mat4, maxShadowedDirectionalLights * maxCascades> worldToAtlas{};
    std::array<CascadeData, maxCascades> cascades{}; // per cascade, shared by every light
    ShadowDistanceFade fade;
    float atlasSize = 0.0f; // texels on a side
    std::int32_t cascadeCount = 0;
    ShadowFilter defaultFilter = ShadowFilter::PCF2x2; // of a light without its own
    CascadeBlend cascadeBlend = CascadeBlend::Hard;
    std::int32_t shadowedLightCount = 0;
    CascadeProjection cascadeProjection = CascadeProjection::Stable;
    alignas(16) std::array<DirectionalShadowLight, maxShadowedDirectionalLights> lights{};
    std::array<DirectionalTileSoft, maxShadowedDirectionalLights * maxCascades> tileSoft{}; // per tile
    SoftShadowUniforms soft;
    // Per tile: its first and last texel in the atlas (ShadowAtlasLayout::tileTexelBounds).
    std::array<TileTexelBounds, maxShadowedDirectionalLights * maxCascades> tileBounds{};
};

inline constexpr std::array kDirectionalShadowFields{
    PENUMBRA_SHADER_FIELD(DirectionalShadowUniforms, worldToAtlas),
    PENUMBRA_SHADER_STRUCT_FIELD(DirectionalShadowUniforms, cascades, kCascadeDataStruct),
    PENUMBRA_SHADER_STRUCT_FIELD(DirectionalShadowUniforms, fade, kShadowDistanceFadeStruct),
    PENUMBRA_SHADER_FIELD(DirectionalShadowUniforms, atlasSize),
    PENUMBRA_SHADER_FIELD(DirectionalShadowUniforms, cascadeCount),
    PENUMBRA_SHADER_FIELD(DirectionalShadowUniforms, defaultFilter),
    PENUMBRA_SHADER_FIELD(DirectionalShadowUniforms, cascadeBlend),
    PENUMBRA_SHADER_FIELD(DirectionalShadowUniforms, shadowedLightCount),
    PENUMBRA_SHADER_FIELD(DirectionalShadowUniforms, cascadeProjection),
    PENUMBRA_SHADER_STRUCT_FIELD(DirectionalShadowUniforms, lights, kDirectionalShadowLightStruct),
    PENUMBRA_SHADER_STRUCT_FIELD(DirectionalShadowUniforms, tileSoft, kDirectionalTileSoftStruct),
    PENUMBRA_SHADER_STRUCT_FIELD(DirectionalShadowUniforms, soft, kSoftShadowStruct),
    PENUMBRA_SHADER_STRUCT_FIELD(DirectionalShadowUniforms, tileBounds, kTileTexelBoundsStruct),
};
// The block DirectionalShadows, read through the instance name `shadows`.
inline constexpr shaders::ShaderStruct kDirectionalShadowBlock{"DirectionalShadows", sizeof(DirectionalShadowUniforms),
                                                               kDirectionalShadowFields};
static_assert(shaders::matchesLayout(kDirectionalShadowBlock, shaders::BlockLayout::Std140));

} // namespace penumbra::shadows
