#pragma once

#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shadows/LocalShadowUniforms.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"
#include "penumbra/shadows/SoftShadowUniforms.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace penumbra::shadows {

inline constexpr std::uint32_t maxStaticDirectionalMaps = 4;
// Tiles of the static local atlas: more than the realtime atlas's 16, so lights that get no realtime tile keep their
// static shadows (up to ten point lights).
inline constexpr std::uint32_t maxStaticLocalTiles = 64;
// Per directional light of the lit pass (render::maxLitDirectionalLights): the lights the lit shader can look a static
// map up for. Spot and point lights find theirs in StaticShadowPlan::localLightMaps, whatever their number.
inline constexpr std::uint32_t maxStaticMapDirectionalLights = 8;

// A directional light's static map as the lit shader reads it (StaticShadowUniforms::directionalLights).
struct alignas(16) StaticDirectionalLight {
    std::int32_t tile = -1; // its tile in the static directional atlas, -1: the light has no static map
    float strength = 0.0f; // the light's shadow strength
    float normalOffset = 0.0f; // the receiver-side normal offset in world units, 0 where the caster side takes it
    ShadowFilter shadowFilter = ShadowFilter::PCF2x2;
};

inline constexpr std::array kStaticDirectionalLightFields{
    PENUMBRA_SHADER_FIELD(StaticDirectionalLight, tile),
    PENUMBRA_SHADER_FIELD(StaticDirectionalLight, strength),
    PENUMBRA_SHADER_FIELD(StaticDirectionalLight, normalOffset),
    PENUMBRA_SHADER_FIELD(StaticDirectionalLight, shadowFilter),
};
inline constexpr shaders::ShaderStruct kStaticDirectionalLightStruct{"StaticDirectionalLight",
                                                                     sizeof(StaticDirectionalLight),
                                                                     kStaticDirectionalLightFields};

// What the Poisson and PCSS filters need of a static directional tile besides its soft data.
struct alignas(16) StaticDirectionalSource {
    float tanHalfAngle = 0.0f; // tan of half the light's angular diameter
    float texelWorldSize = 0.0f; // the world size of a texel of the map
};

inline constexpr std::array kStaticDirectionalSourceFields{
    PENUMBRA_SHADER_FIELD(StaticDirectionalSource, tanHalfAngle),
    PENUMBRA_SHADER_FIELD(StaticDirectionalSource, texelWorldSize),
};
inline constexpr shaders::ShaderStruct kStaticDirectionalSourceStruct{"StaticDirectionalSource",
                                                                      sizeof(StaticDirectionalSource),
                                                                      kStaticDirectionalSourceFields};

// A spot or point light's static map as the lit shader finds it (StaticShadowPlan::localLightMaps).
struct StaticLocalLightMap {
    std::int32_t tile = -1; // the first tile of its static map, -1: the light has none
    float strength = 0.0f; // the light's shadow strength

    bool operator==(const StaticLocalLightMap&) const = default;
};

// The GLSL struct StaticLocalLightMap (static_shadows.glsl), made from the local light texture's texel.
inline constexpr std::array kStaticLocalLightMapFields{
    PENUMBRA_SHADER_FIELD(StaticLocalLightMap, tile),
    PENUMBRA_SHADER_FIELD(StaticLocalLightMap, strength),
};
inline constexpr shaders::ShaderStruct kStaticLocalLightMapStruct{"StaticLocalLightMap", sizeof(StaticLocalLightMap),
                                                                  kStaticLocalLightMapFields};

// The lit shader's static shadow block StaticShadows (static_shadows.glsl), uploaded as is.
struct StaticShadowUniforms {
    // Per directional tile: world -> (u, v, depth) in the static directional atlas.
    std::array<glm::mat4, maxStaticDirectionalMaps> directionalWorldToMap{};
    std::array<TileTexelBounds, maxStaticDirectionalMaps> directionalBounds{}; // per tile: first and last texel
    std::array<StaticDirectionalLight, maxStaticMapDirectionalLights> directionalLights{}; // per directional light
    // Per spot and point tile: world -> (u, v, depth) x w (divide by w).
    std::array<glm::mat4, maxStaticLocalTiles> localWorldToMap{};
    std::array<TileTexelBounds, maxStaticLocalTiles> localBounds{}; // per tile: first and last texel
    std::array<LocalShadowTile, maxStaticLocalTiles> localTiles{}; // per spot and point tile
    float directionalAtlasSize = 0.0f; // texels on a side
    float localAtlasSize = 0.0f;
    // Per directional tile, for the Poisson and PCSS filters, as DirectionalShadowUniforms::tileSoft.
    std::array<DirectionalTileSoft, maxStaticDirectionalMaps> directionalSoft{};
    std::array<StaticDirectionalSource, maxStaticDirectionalMaps> directionalSource{}; // per directional tile
    std::array<PerspectiveTileSoft, maxStaticLocalTiles> localSoft{}; // per spot and point tile
};

inline constexpr std::array kStaticShadowFields{
    PENUMBRA_SHADER_FIELD(StaticShadowUniforms, directionalWorldToMap),
    PENUMBRA_SHADER_STRUCT_FIELD(StaticShadowUniforms, directionalBounds, kTileTexelBoundsStruct),
    PENUMBRA_SHADER_STRUCT_FIELD(StaticShadowUniforms, directionalLights, kStaticDirectionalLightStruct),
    PENUMBRA_SHADER_FIELD(StaticShadowUniforms, localWorldToMap),
    PENUMBRA_SHADER_STRUCT_FIELD(StaticShadowUniforms, localBounds, kTileTexelBoundsStruct),
    PENUMBRA_SHADER_STRUCT_FIELD(StaticShadowUniforms, localTiles, kLocalShadowTileStruct),
    PENUMBRA_SHADER_FIELD(StaticShadowUniforms, directionalAtlasSize),
    PENUMBRA_SHADER_FIELD(StaticShadowUniforms, localAtlasSize),
    PENUMBRA_SHADER_STRUCT_FIELD(StaticShadowUniforms, directionalSoft, kDirectionalTileSoftStruct),
    PENUMBRA_SHADER_STRUCT_FIELD(StaticShadowUniforms, directionalSource, kStaticDirectionalSourceStruct),
    PENUMBRA_SHADER_STRUCT_FIELD(StaticShadowUniforms, localSoft, kPerspectiveTileSoftStruct),
};
// The block StaticShadows, read through the instance name `staticShadows`.
inline constexpr shaders::ShaderStruct kStaticShadowBlock{"StaticShadows", sizeof(StaticShadowUniforms),
                                                          kStaticShadowFields};
static_assert(shaders::matchesLayout(kStaticShadowBlock, shaders::BlockLayout::Std140));

} // namespace penumbra::shadows
