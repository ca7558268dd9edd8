#pragma once

#include "penumbra/rhi/UniformLayout.hpp"
#include "penumbra/shadows/LightVocabulary.hpp"
#include "penumbra/shadows/ShadowCamera.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace penumbra::shadows {

// Clustered light lists: the view frustum cut into tilesX x tilesY screen tiles and `slices` depth slices spaced
// exponentially in view depth (Olsson, Billeter and Assarsson, "Clustered Deferred and Forward Shading", HPG 2012;
// Persson, "Practical Clustered Shading", SIGGRAPH 2015 course), each cluster listing the spot and point lights
// that may reach a point inside it. The lit pass looks up its pixel's cluster and loops over that list only, so its
// cost follows the lights touching a pixel. Lists are conservative: a light that reaches a point of a cluster is in
// that cluster's list (a light may be listed where it reaches nothing).
//
// Cluster (x, y, slice) is number x + tilesX * (y + tilesY * slice); tile x counts from the left edge of the screen,
// y from the TOP (row 0 is the top, as the canonical convention's framebuffer rows), slice from the near plane.

inline constexpr std::uint32_t kDefaultClusterTilesX = 16;
inline constexpr std::uint32_t kDefaultClusterTilesY = 9;
inline constexpr std::uint32_t kDefaultClusterSlices = 24;

// The grid as the lit shader reads it (std140, uploaded as is; the GLSL block is to be generated from
// lightClusterLayout()). A pixel at NDC (x, y) and view depth d (> 0, along the camera's forward axis) lies in
//   tile x = floor((x + 1) / 2 * tilesX), tile y = floor((1 - y) / 2 * tilesY),
//   slice = floor(log(d) * sliceScale + sliceBias), each clamped to its range.
struct LightClusterUniforms {
    std::uint32_t tilesX = kDefaultClusterTilesX;
    std::uint32_t tilesY = kDefaultClusterTilesY;
    std::uint32_t slices = kDefaultClusterSlices;
    std::uint32_t indexCount = 0; // entries of the light index list, all clusters together
    float nearPlane = 0.1f; // view depth where slice 0 begins
    float farPlane = 1000.0f; // view depth where the last slice ends
    float sliceScale = 0.0f; // slices / log(farPlane / nearPlane)
    float sliceBias = 0.0f; // -log(nearPlane) * sliceScale
};

static_assert(offsetof(LightClusterUniforms, nearPlane) == 16);
static_assert(sizeof(LightClusterUniforms) == 32);

// One cluster's list in the index buffer (std430 uvec2): lightIndices[offset .. offset + count).
struct LightClusterRange {
    std::uint32_t offset = 0;
    std::uint32_t count = 0;
};

static_assert(sizeof(LightClusterRange) == 8);

inline rhi::UniformLayout lightClusterLayout()
{
    return {"LightClusters",
            sizeof(LightClusterUniforms),
            {
                PENUMBRA_UNIFORM_MEMBER(LightClusterUniforms, tilesX),
                PENUMBRA_UNIFORM_MEMBER(LightClusterUniforms, tilesY),
                PENUMBRA_UNIFORM_MEMBER(LightClusterUniforms, slices),
                PENUMBRA_UNIFORM_MEMBER(LightClusterUniforms, indexCount),
                PENUMBRA_UNIFORM_MEMBER(LightClusterUniforms, nearPlane),
                PENUMBRA_UNIFORM_MEMBER(LightClusterUniforms, farPlane),
                PENUMBRA_UNIFORM_MEMBER(LightClusterUniforms, sliceScale),
                PENUMBRA_UNIFORM_MEMBER(LightClusterUniforms, sliceBias),
            }};
}

// A light's reach: a point light's sphere, or a spot light's cone (the points within `range` of the light and within
// `outerAngle` of its axis).
struct ClusterLight {
    LightKind kind = LightKind::Point;
    glm::vec3 position{0.0f};
    float range = 10.0f; // > 0
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // spot: unit axis, away from the light
    float outerAngle = 0.6f; // spot: half-angle, radians, below pi / 2
};

// The froxel grid's resolution: screen tiles across and down, depth slices.
struct LightClusterGridDesc {
    std::uint32_t tilesX = kDefaultClusterTilesX;
    std::uint32_t tilesY = kDefaultClusterTilesY;
    std::uint32_t slices = kDefaultClusterSlices;
};

// A view's clusters and the lights each may reach, flat for a GPU buffer or texture.
struct LightClusters {
    LightClusterUniforms grid;
    std::vector<LightClusterRange> ranges; // per cluster, in cluster order
    std::vector<std::uint32_t> lightIndices; // indices into the lights given, ascending within each cluster
};

// Lists each light in every cluster its reach may touch. The camera's near and far planes bound the slices.
// Throws rhi::Error for a grid with 0 (or more than 256) tiles or slices on an axis, a camera with no depth range
// (0 < nearPlane < farPlane) or a light whose range is not positive or whose spot angle is not in (0, pi / 2).
LightClusters buildLightClusters(const ShadowCamera& camera, std::span<const ClusterLight> lights,
                                 const LightClusterGridDesc& desc = {});

// The cluster of a point at NDC (x, y) and view depth `depth`, as the lit shader finds it.
std::uint32_t clusterIndex(const LightClusterUniforms& grid, glm::vec2 ndc, float depth);

// The cluster of a world-space point seen by `camera`; nullopt outside the view frustum.
std::optional<std::uint32_t> clusterAt(const ShadowCamera& camera, const LightClusterUniforms& grid, glm::vec3 world);

// Whether a light reaches a world-space point: the brute-force reference of the lists.
bool lightReaches(const ClusterLight& light, glm::vec3 world);

} // namespace penumbra::shadows
