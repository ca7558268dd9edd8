#pragma once

#include "penumbra/rhi/UniformLayout.hpp"

#include <array>
#include <cstddef>
#include "penumbra/shadows/SoftShadowUniforms.hpp"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace penumbra::shadows {

inline constexpr std::uint32_t maxShadowedDirectionalLights = 4;
inline constexpr std::uint32_t maxCascades = 4;

// The lit shader's directional-shadow uniform block, std140, uploaded as is. GLSL:
//   layout(std140) uniform DirectionalShadows {
//       mat4 worldToAtlas[16];      // tile light * cascadeCount + cascade: world -> (u, v, depth) in the atlas
//       vec4 cullingSpheres[4];     // xyz centre, w = r'^2 (sphere shrunk by the filter): cascade selection
//       vec4 cascadeData[4];        // x = 1 / r'^2 (cascade fade), y = normal bias in world units per unit bias,
//                                   // z = world size of a texel, w = view depth where the cascade ends (close fit)
//       vec4 distanceFade;          // 1 / maxDistance, 1 / distanceFade, 1 / (1 - (1 - cascadeFade)^2),
//                                   // 1 / cascadeFade
//       float atlasSize;            // texels on a side
//       int cascadeCount;
//       int defaultFilter;          // ShadowFilter of a light without its own
//       int cascadeBlend;           // CascadeBlend (PENUMBRA_BLEND_*)
//       int shadowedLightCount;
//       int cascadeProjection;      // CascadeProjection (PENUMBRA_PROJECTION_*)
//       vec4 lightShadowData[4];    // per shadow slot: strength, normalBias, first tile, the light's filter
//       vec4 tileSoft[16];          // per tile: x, y: add to a tile texel for the light-space texel (the disk's
//                                   // rotation); z, w: the depth row (orthographicDistanceFromNear: the distance
//                                   // past the nearest caster's light-space depth)
//       vec4 lightSoft[4];          // per shadow slot: tan of half the angular diameter, normal bias factor of the
//                                   // light's filter over the atlas's, 0, 0
//       vec4 softScales;            // SoftShadowUniforms
//       vec4 softCounts;
//       vec4 tileBounds[16];        // per tile: its first and last texel's x, y in the atlas (ShadowAtlasLayout::
//                                   // tileTexelBounds), which the filters clamp their taps to: given, not worked
//                                   // out per pixel with an integer division (llvmpipe has no vector one)
//   };
struct DirectionalShadowUniforms {
    std::array<glm::mat4, maxShadowedDirectionalLights * maxCascades> worldToAtlas{};
    std::array<glm::vec4, maxCascades> cullingSpheres{};
    std::array<glm::vec4, maxCascades> cascadeData{};
    glm::vec4 distanceFade{0.0f};
    float atlasSize = 0.0f;
    std::int32_t cascadeCount = 0;
    std::int32_t defaultFilter = 0;
    std::int32_t cascadeBlend = 0;
    std::int32_t shadowedLightCount = 0;
    std::int32_t cascadeProjection = 0;
    alignas(
        16) std::array<glm::vec4, maxShadowedDirectionalLights> lightShadowData{}; // std140: vec4 arrays align to 16
    std::array<glm::vec4, maxShadowedDirectionalLights * maxCascades> tileSoft{};
    std::array<glm::vec4, maxShadowedDirectionalLights> lightSoft{};
    SoftShadowUniforms soft;
    std::array<glm::vec4, maxShadowedDirectionalLights * maxCascades> tileBounds{};
};

static_assert(sizeof(glm::mat4) == 64 && sizeof(glm::vec4) == 16 && sizeof(glm::ivec4) == 16);
static_assert(offsetof(DirectionalShadowUniforms, worldToAtlas) == 0);
static_assert(offsetof(DirectionalShadowUniforms, cullingSpheres) == 1024);
static_assert(offsetof(DirectionalShadowUniforms, cascadeData) == 1088);
static_assert(offsetof(DirectionalShadowUniforms, distanceFade) == 1152);
static_assert(offsetof(DirectionalShadowUniforms, atlasSize) == 1168);
static_assert(offsetof(DirectionalShadowUniforms, cascadeCount) == 1172);
static_assert(offsetof(DirectionalShadowUniforms, lightShadowData) == 1200);
static_assert(offsetof(DirectionalShadowUniforms, tileSoft) == 1264);
static_assert(offsetof(DirectionalShadowUniforms, soft) == 1584);
static_assert(offsetof(DirectionalShadowUniforms, tileBounds) == 1616);
static_assert(sizeof(DirectionalShadowUniforms) == 1872);

// The struct as the PipelineDesc::uniformLayouts entry of the block above.
inline rhi::UniformLayout directionalShadowLayout()
{
    rhi::UniformLayout layout{"DirectionalShadows",
                              sizeof(DirectionalShadowUniforms),
                              {
                                  PENUMBRA_UNIFORM_MEMBER(DirectionalShadowUniforms, worldToAtlas),
                                  PENUMBRA_UNIFORM_MEMBER(DirectionalShadowUniforms, cullingSpheres),
                                  PENUMBRA_UNIFORM_MEMBER(DirectionalShadowUniforms, cascadeData),
                                  PENUMBRA_UNIFORM_MEMBER(DirectionalShadowUniforms, distanceFade),
                                  PENUMBRA_UNIFORM_MEMBER(DirectionalShadowUniforms, atlasSize),
                                  PENUMBRA_UNIFORM_MEMBER(DirectionalShadowUniforms, cascadeCount),
                                  PENUMBRA_UNIFORM_MEMBER(DirectionalShadowUniforms, defaultFilter),
                                  PENUMBRA_UNIFORM_MEMBER(DirectionalShadowUniforms, cascadeBlend),
                                  PENUMBRA_UNIFORM_MEMBER(DirectionalShadowUniforms, shadowedLightCount),
                                  PENUMBRA_UNIFORM_MEMBER(DirectionalShadowUniforms, cascadeProjection),
                                  PENUMBRA_UNIFORM_MEMBER(DirectionalShadowUniforms, lightShadowData),
                                  PENUMBRA_UNIFORM_MEMBER(DirectionalShadowUniforms, tileSoft),
                                  PENUMBRA_UNIFORM_MEMBER(DirectionalShadowUniforms, lightSoft),
                              }};
    for (rhi::UniformMember& member : softShadowMembers(std::uint32_t(offsetof(DirectionalShadowUniforms, soft))))
        layout.members.push_back(std::move(member));
    layout.members.push_back(PENUMBRA_UNIFORM_MEMBER(DirectionalShadowUniforms, tileBounds));
    return layout;
}

} // namespace penumbra::shadows
