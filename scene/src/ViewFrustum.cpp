#include "penumbra/scene/ViewFrustum.hpp"

#include <cmath>
#include <glm/geometric.hpp>

namespace penumbra::scene {
namespace {

glm::vec4 plane(const glm::vec3& normal, const glm::vec3& through)
{
    const glm::vec3 n = glm::normalize(normal);
    return {n, -glm::dot(n, through)};
}

} // namespace

ViewFrustum::ViewFrustum(const Camera& camera, float aspect)
{
    const glm::vec3 forward = glm::normalize(camera.forward);
    const glm::vec3 right = camera.right();
    const glm::vec3 up = glm::cross(right, forward);
    const float tanY = std::tan(0.5f * camera.fovY);
    const float tanX = tanY * aspect;
    const glm::vec3& eye = camera.position;
    // The side planes pass through the eye; each normal points from the plane into the volume.
    planes_ = {plane(forward, eye + camera.nearPlane * forward),
               plane(-forward, eye + camera.farPlane * forward),
               plane(forward * tanX + right, eye),
               plane(forward * tanX - right, eye),
               plane(forward * tanY + up, eye),
               plane(forward * tanY - up, eye)};
}

bool ViewFrustum::mayShow(const Bounds& box) const
{
    for (const glm::vec4& p : planes_) {
        const glm::vec3 normal(p);
        // The box corner farthest along the normal: if even it lies outside, the whole box does. The slack covers
        // the rounding of the dot product, so a box the GPU would still rasterize is never dropped.
        const glm::vec3 corner(normal.x >= 0.0f ? box.max.x : box.min.x, normal.y >= 0.0f ? box.max.y : box.min.y,
                               normal.z >= 0.0f ? box.max.z : box.min.z);
        const float along = glm::dot(normal, corner);
        if (along + p.w < -1e-5f * (std::abs(along) + std::abs(p.w)))
            return false;
    }
    return true;
}

} // namespace penumbra::scene
