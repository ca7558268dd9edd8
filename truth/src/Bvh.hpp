#pragma once

#include "penumbra/scene/Geometry.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace penumbra::truth {

// Node of a flattened binary BVH, 32 bytes so two share a cache line.
// Leaf: count > 0 primitives from Bvh::order[first]. Interior: count == 0, children at
// first and first + 1.
struct BvhNode {
    glm::vec3 min;
    std::uint32_t first;
    glm::vec3 max;
    std::uint32_t count;
};
static_assert(sizeof(BvhNode) == 32);

// Deeper ranges become leaves whatever their size, so a traversal stack of
// kBvhMaxDepth + 1 entries never overflows.
inline constexpr std::uint32_t kBvhMaxDepth = 64;

struct Bvh {
    std::vector<BvhNode> nodes; // nodes[0] is the root (absent when there are no primitives)
    std::vector<std::uint32_t> order; // primitive indices, grouped by leaf
};

// Top-down build with a binned surface area heuristic over primitive centroids.
Bvh buildBvh(std::span<const scene::Bounds> primitiveBounds);

} // namespace penumbra::truth
