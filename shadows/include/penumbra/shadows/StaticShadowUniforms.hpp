#pragma once

#include "penumbra/rhi/UniformLayout.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace penumbra::shadows {

inline constexpr std::uint32_t maxStaticDirectionalMaps = 4;
// Tiles of the static other atlas: more than the realtime atlas's 16, so lights that get no realtime tile keep their
// static shadows (up to ten point lights).
inline constexpr std::uint32_t maxStaticOtherTiles = 64;
// Per light of the lit pass (render::maxLitDirectionalLights, render::maxLitLocalLights): the lights the lit shader
// can look a static map up for.
inline constexpr std::uint32_t maxStaticMapDirectionalLights = 8;
inline constexpr std::uint32_t maxStaticMapLocalLights = 16;

// The lit shader's static shadow block, std140, uploaded as is. GLSL (shaders/static_shadows.glsl):
//   layout(std140) uniform StaticShadows {
//       mat4 directionalWorldToMap[4]; // per directional tile: world -> (u, v, depth) in the static directional atlas
//       vec4 directionalBounds[4];     // per directional tile: first and last texel (x, y, x, y)
//       vec4 directionalLights[8];     // per directional light: tile or -1, shadow strength, normal offset (world
//                                      // units), filter (ShadowFilter)
//       mat4 otherWorldToMap[64];      // per spot and point tile: world -> (u, v, depth) x w (divide by w)
//       vec4 otherBounds[64];          // per tile: first and last texel
//       vec4 otherData[64];            // per tile: normal bias per unit distance from the light plane, filter, 0, 0
//       vec4 localLights[16];          // per spot light, then point light: first tile or -1, shadow strength, 0, 0
//       vec4 atlasSizes;               // directional atlas size, other atlas size, 0, 0
//       vec4 directionalSoft[4];       // per directional tile, for the Poisson and PCSS filters: the light texel
//                                      // anchor (x, y) and the depth row (z, w), as DirectionalShadowUniforms::tileSoft
//       vec4 directionalSource[4];     // per directional tile: tan of half the light's angular diameter, the world
//                                      // size of a texel, 0, 0
//       vec4 otherSoft[64];            // per spot and point tile: the depth row (t22, t32), the light's radius in
//                                      // texels at unit distance, the near plane, as OtherShadowUniforms::tileSoft
//   };
struct StaticShadowUniforms {
    std::array<glm::mat4, maxStaticDirectionalMaps> directionalWorldToMap{};
    std::array<glm::vec4, maxStaticDirectionalMaps> directionalBounds{};
    std::array<glm::vec4, maxStaticMapDirectionalLights> directionalLights{};
    std::array<glm::mat4, maxStaticOtherTiles> otherWorldToMap{};
    std::array<glm::vec4, maxStaticOtherTiles> otherBounds{};
    std::array<glm::vec4, maxStaticOtherTiles> otherData{};
    std::array<glm::vec4, maxStaticMapLocalLights> localLights{};
    glm::vec4 atlasSizes{0.0f};
    std::array<glm::vec4, maxStaticDirectionalMaps> directionalSoft{};
    std::array<glm::vec4, maxStaticDirectionalMaps> directionalSource{};
    std::array<glm::vec4, maxStaticOtherTiles> otherSoft{};

    // No light has a static map.
    StaticShadowUniforms()
    {
        directionalLights.fill(glm::vec4(-1.0f, 0.0f, 0.0f, 0.0f));
        localLights.fill(glm::vec4(-1.0f, 0.0f, 0.0f, 0.0f));
    }
};

static_assert(offsetof(StaticShadowUniforms, directionalBounds) == 256);
static_assert(offsetof(StaticShadowUniforms, otherWorldToMap) == 448);
static_assert(offsetof(StaticShadowUniforms, otherBounds) == 4544);
static_assert(offsetof(StaticShadowUniforms, localLights) == 6592);
static_assert(offsetof(StaticShadowUniforms, directionalSoft) == 6864);
static_assert(sizeof(StaticShadowUniforms) == 8016);

// The struct as the PipelineDesc::uniformLayouts entry of the block above.
inline rhi::UniformLayout staticShadowLayout()
{
    return {"StaticShadows", sizeof(StaticShadowUniforms),
            {
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, directionalWorldToMap),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, directionalBounds),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, directionalLights),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, otherWorldToMap),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, otherBounds),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, otherData),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, localLights),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, atlasSizes),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, directionalSoft),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, directionalSource),
                PENUMBRA_UNIFORM_MEMBER(StaticShadowUniforms, otherSoft),
            }};
}

} // namespace penumbra::shadows
