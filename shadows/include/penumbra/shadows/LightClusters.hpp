#pragma once

#include "penumbra/rhi/UniformLayout.hpp"
#include "penumbra/shadows/LightVocabulary.hpp"
#include "penumbra/shadows/ShadowCamera.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

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

// Each cluster's view-space box is widened by this fraction of its far depth, so that rounding at the lookup's floor()
// never leaves a light out.
inline constexpr float kClusterBoxMargin = 1e-3f;

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

// One light as the cluster tests take it, in the camera's view space (x right, y up, z the view depth): what
// buildLightClusters works out per light before its loop over the clusters, and what the GPU build
// (GpuLightClusters) reads, so that both test the same numbers. An element of a std430 storage block.
struct alignas(16) ClusterLightBound {
    glm::vec4 bound{0.0f}; // the smallest sphere around the light's reach: centre, radius
    glm::vec4 reach{0.0f}; // the range sphere: the light's position, its range
    glm::vec4 axis{0.0f}; // a spot light's unit axis with w = 1; w = 0 for a point light
    glm::vec4 cone{0.0f}; // a spot light's cos and sin of its outer angle
    glm::ivec4 tiles{1, 0, 0, 0}; // first x, first y, last x, last y of the tiles it may cover; none where x > z
    glm::ivec4 slices{1, 0, 0, 0}; // its first and last slice; none where x > y
};

// What the cluster tests take for a view: the grid, its tiles' and slices' edges and every light's bound.
struct LightClusterInputs {
    LightClusterUniforms grid; // indexCount stays 0: the lists are not built yet
    glm::vec2 tanHalf{0.0f}; // tangents of the half fields of view across and down
    std::vector<float> edgesX; // tilesX + 1 NDC x of the tiles' edges, from the left
    std::vector<float> edgesY; // tilesY + 1 NDC y of the tiles' edges, from the top
    std::vector<float> depths; // slices + 1 view depths of the slices' ends, from the near plane
    std::vector<ClusterLightBound> lights; // in the order given
    std::uint64_t entryBound = 0; // no list holds more entries in all: each light's tiles times its slices, summed
};

// The inputs of buildLightClusters, validated as it validates them.
LightClusterInputs lightClusterInputs(const ShadowCamera& camera, std::span<const ClusterLight> lights,
                                      const LightClusterGridDesc& desc = {});

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
