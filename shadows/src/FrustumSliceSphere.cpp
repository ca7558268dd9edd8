#include "penumbra/shadows/FrustumSliceSphere.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace penumbra::shadows {

std::array<glm::vec3, 8> frustumSliceCorners(const ShadowCamera& camera, float nearDistance, float farDistance)
{
    const glm::vec3 right = glm::cross(camera.forward, camera.up);
    const float tanY = std::tan(0.5f * camera.fovY);
    std::array<glm::vec3, 8> corners;
    int i = 0;
    for (float d : {nearDistance, farDistance}) {
        const glm::vec3 centre = camera.position + camera.forward * d;
        const float h = d * tanY;
        const float w = h * camera.aspect;
        for (float sy : {-1.0f, 1.0f})
            for (float sx : {-1.0f, 1.0f})
                corners[i++] = centre + right * (sx * w) + camera.up * (sy * h);
    }
    return corners;
}

Sphere frustumSliceSphere(const ShadowCamera& camera, float nearDistance, float farDistance)
{
    // A corner at depth d lies k * d off the axis, k^2 = tan^2(fovY / 2) (1 + aspect^2). Equal distance
    // to near and far corners puts the centre at z = (n + f)(1 + k^2) / 2; past f, the far rectangle's
    // circumscribed circle (centre f, radius k f) already holds the near corners.
    const float tanY = std::tan(0.5f * camera.fovY);
    const float k2 = tanY * tanY * (1.0f + camera.aspect * camera.aspect);
    const float n = nearDistance;
    const float f = farDistance;
    const float z = std::min(0.5f * (n + f) * (1.0f + k2), f);
    const float radius = std::sqrt((f - z) * (f - z) + k2 * f * f);
    return {camera.position + camera.forward * z, radius};
}

} // namespace penumbra::shadows
