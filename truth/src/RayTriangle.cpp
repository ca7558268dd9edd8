#include "penumbra/truth/RayTriangle.hpp"

#include "MollerTrumbore.hpp"

namespace penumbra::truth {

std::optional<TriangleHit> intersectRayTriangle(const glm::vec3& origin, const glm::vec3& direction,
                                                const glm::vec3& v0, const glm::vec3& v1, const glm::vec3& v2,
                                                float maxDistance)
{
    return detail::intersectEdges(origin, direction, v0, v1 - v0, v2 - v0, maxDistance);
}

} // namespace penumbra::truth
