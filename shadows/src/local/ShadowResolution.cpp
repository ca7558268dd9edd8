#include "penumbra/shadows/ShadowResolution.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace penumbra::shadows {
namespace {

// A side plane of the view frustum through the camera, at half-angle `halfAngle` off the view axis: the sphere lies
// wholly outside when its centre is more than `radius` beyond it (`across`: the centre's offset across the axis
// towards that plane, `depth`: along the axis).
bool beyondSidePlane(float across, float depth, float halfAngle, float radius)
{
    return across * std::cos(halfAngle) - depth * std::sin(halfAngle) > radius;
}

} // namespace

float projectedSphereHeight(const ShadowCamera& camera, glm::vec3 centre, float radius)
{
    const glm::vec3 offset = centre - camera.position;
    const float distance = glm::length(offset);
    if (distance <= radius)
        return 1.0f;
    const glm::vec3 right = glm::normalize(glm::cross(camera.forward, camera.up));
    const float depth = glm::dot(offset, camera.forward);
    const float x = glm::dot(offset, right);
    const float y = glm::dot(offset, camera.up);
    const float halfY = 0.5f * camera.fovY;
    const float halfX = std::atan(camera.aspect * std::tan(halfY));
    if (depth < camera.nearPlane - radius || depth > camera.farPlane + radius ||
        beyondSidePlane(y, depth, halfY, radius) || beyondSidePlane(-y, depth, halfY, radius) ||
        beyondSidePlane(x, depth, halfX, radius) || beyondSidePlane(-x, depth, halfX, radius))
        return 0.0f;
    // The silhouette's angular radius: sin = radius / distance.
    const float tangent = radius / std::sqrt(distance * distance - radius * radius);
    return std::min(1.0f, tangent / std::tan(halfY));
}

float localShadowPriority(const ShadowCamera& camera, const LocalLightImportance& light)
{
    return projectedSphereHeight(camera, light.position, light.range) *
           std::sqrt(std::clamp(light.relativeIntensity, 0.0f, 1.0f));
}

ShadowResolutionRequest localShadowRequest(const ShadowCamera& camera, const LocalLightImportance& light,
                                           const ShadowResolutionLimits& limits)
{
    if (!(limits.floorSize > 0.0f && limits.floorSize <= limits.maxSize && std::isfinite(limits.maxSize)))
        throw rhi::Error(fmt::format("shadow resolution limits: floorSize {} and maxSize {}, allowed 0 < floorSize <= "
                                     "maxSize",
                                     limits.floorSize, limits.maxSize));
    if (!(light.range > 0.0f && std::isfinite(light.range)))
        throw rhi::Error(fmt::format("shadow resolution: range {}, allowed a positive finite number", light.range));
    const float own = light.shadowResolution.value_or(limits.defaultSize);
    if (!(own > 0.0f && std::isfinite(own)))
        throw rhi::Error(
            fmt::format("shadow resolution: the light's own resolution is {}, allowed a positive finite number", own));
    const float priority = localShadowPriority(camera, light);
    return {std::clamp(own * priority, limits.floorSize, limits.maxSize), priority};
}

} // namespace penumbra::shadows
