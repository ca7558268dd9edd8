#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>

namespace penumbra::truth {

// Where a ray meets a triangle: origin + distance * direction, and barycentrics (u, v)
// weighting v1 and v2 (v0's weight is 1 - u - v).
struct TriangleHit {
    float distance;
    glm::vec2 barycentrics;
};

// Moller-Trumbore, two-sided: either side is hit (RayCaster decides which sides count).
// Hits with 0 < distance <= maxDistance count; distance is in units of |direction|.
// Edge-on rays and degenerate triangles miss.
std::optional<TriangleHit> intersectRayTriangle(const glm::vec3& origin, const glm::vec3& direction,
                                                const glm::vec3& v0, const glm::vec3& v1, const glm::vec3& v2,
                                                float maxDistance);

} // namespace penumbra::truth
