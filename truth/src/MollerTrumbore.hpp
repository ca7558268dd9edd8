#pragma once

#include "penumbra/truth/RayTriangle.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace penumbra::truth::detail {

// Moller-Trumbore on a triangle stored as v0 and its edges e1 = v1 - v0, e2 = v2 - v0 (the
// ray caster keeps them precomputed). Shared by intersectRayTriangle and the BVH traversal.
inline std::optional<TriangleHit> intersectEdges(const glm::vec3& origin, const glm::vec3& direction,
                                                 const glm::vec3& v0, const glm::vec3& e1, const glm::vec3& e2,
                                                 float maxDistance)
{
    const glm::vec3 p = glm::cross(direction, e2);
    const float determinant = glm::dot(e1, p);
    // Zero when the ray runs in the triangle's plane or the triangle has no area.
    if (std::abs(determinant) < std::numeric_limits<float>::min())
        return std::nullopt;
    const float inverse = 1.0f / determinant;
    const glm::vec3 s = origin - v0;
    const float u = glm::dot(s, p) * inverse;
    if (u < 0.0f || u > 1.0f)
        return std::nullopt;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(direction, q) * inverse;
    if (v < 0.0f || u + v > 1.0f)
        return std::nullopt;
    const float t = glm::dot(e2, q) * inverse;
    if (!(t > 0.0f && t <= maxDistance))
        return std::nullopt;
    return TriangleHit{t, {u, v}};
}

} // namespace penumbra::truth::detail
