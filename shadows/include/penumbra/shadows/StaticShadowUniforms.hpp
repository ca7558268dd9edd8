#pragma once

#include "penumbra/shaders/ShaderBlock.hpp"

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

// The lit shader's static shadow block StaticShadows (static_shadows.glsl), uploaded as is.
struct StaticShadowUniforms {
    // Per directional tile: world -> (u, v, depth) in the static directional atlas.
    std::array<glm::mat4, maxStaticDirectionalMaps> directionalWorldToMap{};
    std::array<glm::vec4, maxStaticDirectionalMaps> directionalBounds{}; // per tile: first and last texel (x, y, x, y)
    // Per directional light: tile or -1, shadow strength, normal offset (world units), filter (ShadowFilter).
    std::array<glm::vec4, maxStaticMapDirectionalLights> directionalLights{};
    // Per spot and point tile: world -> (u, v, depth) x w (divide by w).
    std::array<glm::mat4, maxStaticLocalTiles> localWorldToMap{};
    std::array<glm::vec4, maxStaticLocalTiles> localBounds{}; // per tile: first and last texel
    // Per tile: normal bias per unit distance from the light plane, filter, 0, 0.
    std::array<glm::vec4, maxStaticLocalTiles> localData{};
    glm::vec4 atlasSizes{0.0f}; // directional atlas size, local atlas size, 0, 0
    // Per directional tile, for the Poisson and PCSS filters: the light texel anchor (x, y) and the depth row (z, w),
    // as DirectionalShadowUniforms::tileSoft.
    std::array<glm::vec4, maxStaticDirectionalMaps> directionalSoft{};
    // Per directional tile: tan of half the light's angular diameter, the world size of a texel, 0, 0.
    std::array<glm::vec4, maxStaticDirectionalMaps> directionalSource{};
    // Per spot and point tile: the depth row (t22, t32), the light's radius in texels at unit distance, the near
    // plane, as LocalShadowUniforms::tileSoft.
    std::array<glm::vec4, maxStaticLocalTiles> localSoft{};

    // No light has a static map.
    StaticShadowUniforms() { directionalLights.fill(glm::vec4(-1.0f, 0.0f, 0.0f, 0.0f)); }
};

inline constexpr std::array kStaticShadowFields{
    PENUMBRA_SHADER_FIELD(StaticShadowUniforms, directionalWorldToMap),
    PENUMBRA_SHADER_FIELD(StaticShadowUniforms, directionalBounds),
    PENUMBRA_SHADER_FIELD(StaticShadowUniforms, directionalLights),
    PENUMBRA_SHADER_FIELD(StaticShadowUniforms, localWorldToMap),
    PENUMBRA_SHADER_FIELD(StaticShadowUniforms, localBounds),
    PENUMBRA_SHADER_FIELD(StaticShadowUniforms, localData),
    PENUMBRA_SHADER_FIELD(StaticShadowUniforms, atlasSizes),
    PENUMBRA_SHADER_FIELD(StaticShadowUniforms, directionalSoft),
    PENUMBRA_SHADER_FIELD(StaticShadowUniforms, directionalSource),
    PENUMBRA_SHADER_FIELD(StaticShadowUniforms, localSoft),
};
// The block StaticShadows, read through the instance name `staticShadows`.
inline constexpr shaders::ShaderStruct kStaticShadowBlock{"StaticShadows", sizeof(StaticShadowUniforms),
                                                          kStaticShadowFields};
static_assert(shaders::matchesLayout(kStaticShadowBlock, shaders::BlockLayout::Std140));

} // namespace penumbra::shadows
