#pragma once

#include "penumbra/rhi/UniformLayout.hpp"

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

// The lit shader's static shadow block, std140, uploaded as is. GLSL (shaders/static_shadows.glsl):
//   layout(std140) uniform StaticShadows {
//       mat4 directionalWorldToMap[4]; // per directional tile: world -> (u, v, depth) in the static directional atlas
//       vec4 directionalBounds[4];     // per directional tile: first and last texel (x, y, x, y)
//       vec4 directionalLights[8];     // per directional light: tile or -1, shadow strength, normal offset (world
//                                      // units), filter (ShadowFilter)
//       mat4 localWorldToMap[64];      // per spot and point tile: world -> (u, v, depth) x w (divide by w)
//       vec4 localBounds[64];          // per tile: first and last texel
//       vec4 localData[64];            // per tile: normal bias per unit distance from the light plane, filter, 0, 0
//       vec4 atlasSizes;               // directional atlas size, local atlas size, 0, 0
//       vec4 directionalSoft[4];       // per directional tile, for the Poisson and PCSS filters: the light texel
//                                      // anchor (x, y) and the depth row (z, w), as
//                                      DirectionalShadowUniforms::tileSoft
//       vec4 directionalSource[4];     // per directional tile: tan of half the light's angular diameter, the world
//                                      // size of a texel, 0, 0
//       vec4 localSoft[64];            // per spot and point tile: the depth row (t22, t32), the light's radius in
//                                      // texels at unit distance, the near plane, as LocalShadowUniforms::tileSoft
//   };
struct StaticShadowUniforms {
    std::array<glm::mat4, maxStaticDirectionalMaps> directionalWorldToMap{};
    std::array<glm::vec4, maxStaticDirectionalMaps> directionalBounds{};
    std::array<glm::vec4, maxStaticMapDirectionalLights> directionalLights{};
    std::array<glm::mat4, maxStaticLocalTiles> localWorldToMap{};
    std::array<glm::vec4, maxStaticLocalTiles> localBounds{};
    std::array<glm::vec4, maxStaticLocalTiles> localData{};
    glm::vec4 atlasSizes{0.0f};
    std::array<glm::vec4, maxStaticDirectionalMaps> directionalSoft{};
    std::array<glm::vec4, maxStaticDirectionalMaps> directionalSource{};
    std::array<glm::vec4, maxStaticLocalTiles> localSoft{};

    // No light has a static map.
    StaticShadowUniforms() { directionalLights.fill(glm::vec4(-1.0f, 0.0f, 0.0f, 0.0f)); }
};

static_assert(offsetof(StaticShadowUniforms, directionalBounds) == 256);
static_assert(offsetof(StaticShadowUniforms, localWorldToMap) == 448);
static_assert(offsetof(StaticShadowUniforms, localBounds) == 4544);
static_assert(offsetof(StaticShadowUniforms, atlasSizes) == 6592);
static_assert(offsetof(StaticShadowUniforms, directionalSoft) == 6608);
static_assert(sizeof(StaticShadowUniforms) == 7760);

// The struct as the PipelineDesc::uniformLayouts entry of the block above.
inline rhi::UniformLayout staticShadowLayout()
{
    return {"StaticShadows",
            sizeof(StaticShadowUniforms),
            {
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, directionalWorldToMap),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, directionalBounds),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, directionalLights),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, localWorldToMap),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, localBounds),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, localData),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, atlasSizes),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, directionalSoft),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, directionalSource),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, localSoft),
            }};
}

} // namespace penumbra::shadows
