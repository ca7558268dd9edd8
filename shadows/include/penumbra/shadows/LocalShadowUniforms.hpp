#pragma once

#include "penumbra/rhi/UniformLayout.hpp"

#include <array>
#include <cstddef>
#include "penumbra/shadows/SoftShadowUniforms.hpp"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace penumbra::shadows {

inline constexpr std::uint32_t maxLocalShadowTiles = 16;
inline constexpr std::uint32_t maxShadowCubes = 4;

// The lit shader's spot and point shadow block, std140, uploaded as is. GLSL (shaders/local_shadows.glsl):
//   layout(std140) uniform LocalShadows {
//       mat4 worldToAtlas[16]; // per tile: world -> (u, v, depth) x w in the local atlas (divide by w)
//       vec4 tileBounds[16];   // per tile: first and last texel (x, y, x, y) that filter taps may read
//       vec4 tileData[16];     // per tile: x = normal bias per unit distance from the light plane, y = the light's
//                              // filter (ShadowFilter)
//       vec4 cubeData[4];      // per cube: x, y: window depth = (x * -z + y) / z at major-axis distance z,
//                              // z = normal bias per unit distance, w = 1 / face size (texels)
//       float atlasSize;       // texels on a side
//       int defaultFilter;     // ShadowFilter of a light without its own
//       int pointMode;         // PointShadowMode (PENUMBRA_POINT_*)
//       vec4 tileSoft[16];     // per tile: (t22, t32) the depth row (perspectiveDistance), the light's radius in
//                              // texels at unit distance (lightTexels), the near plane
//       vec4 cubeSoft[4];      // per cube: the light's filter, lightTexels, the near plane, 0
//       vec4 softScales;       // SoftShadowUniforms
//       vec4 softCounts;
//   };
struct LocalShadowUniforms {
    std::array<glm::mat4, maxLocalShadowTiles> worldToAtlas{};
    std::array<glm::vec4, maxLocalShadowTiles> tileBounds{};
    std::array<glm::vec4, maxLocalShadowTiles> tileData{};
    std::array<glm::vec4, maxShadowCubes> cubeData{};
    float atlasSize = 0.0f;
    std::int32_t defaultFilter = 0;
    std::int32_t pointMode = 0;
    alignas(16) std::array<glm::vec4, maxLocalShadowTiles> tileSoft{}; // std140: vec4 arrays align to 16
    std::array<glm::vec4, maxShadowCubes> cubeSoft{};
    SoftShadowUniforms soft;
};

static_assert(offsetof(LocalShadowUniforms, tileBounds) == 1024);
static_assert(offsetof(LocalShadowUniforms, tileData) == 1280);
static_assert(offsetof(LocalShadowUniforms, cubeData) == 1536);
static_assert(offsetof(LocalShadowUniforms, atlasSize) == 1600);
static_assert(offsetof(LocalShadowUniforms, defaultFilter) == 1604);
static_assert(offsetof(LocalShadowUniforms, tileSoft) == 1616);
static_assert(offsetof(LocalShadowUniforms, soft) == 1936);
static_assert(sizeof(LocalShadowUniforms) == 1968);

// The struct as the PipelineDesc::uniformLayouts entry of the block above.
inline rhi::UniformLayout localShadowLayout()
{
    rhi::UniformLayout layout{"LocalShadows",
                              sizeof(LocalShadowUniforms),
                              {
                                  PENUMBRA_UNIFORM_MEMBER(LocalShadowUniforms, worldToAtlas),
                                  PENUMBRA_UNIFORM_MEMBER(LocalShadowUniforms, tileBounds),
                                  PENUMBRA_UNIFORM_MEMBER(LocalShadowUniforms, tileData),
                                  PENUMBRA_UNIFORM_MEMBER(LocalShadowUniforms, cubeData),
                                  PENUMBRA_UNIFORM_MEMBER(LocalShadowUniforms, atlasSize),
                                  PENUMBRA_UNIFORM_MEMBER(LocalShadowUniforms, defaultFilter),
                                  PENUMBRA_UNIFORM_MEMBER(LocalShadowUniforms, pointMode),
                                  PENUMBRA_UNIFORM_MEMBER(LocalShadowUniforms, tileSoft),
                                  PENUMBRA_UNIFORM_MEMBER(LocalShadowUniforms, cubeSoft),
                              }};
    for (rhi::UniformMember& member : softShadowMembers(std::uint32_t(offsetof(LocalShadowUniforms, soft))))
        layout.members.push_back(std::move(member));
    return layout;
}

} // namespace penumbra::shadows
