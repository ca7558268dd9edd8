#include "penumbra/shadows/CasterCulling.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace penumbra::shadows {
namespace {

bool overlapsCascade(const Bounds& light, const DirectionalShadowCascade& c)
{
    const glm::vec2 centre = c.snappedCentre;
    const float h = c.halfSize;
    return light.max.x >= centre.x - h && light.min.x <= centre.x + h && light.max.y >= centre.y - h &&
           light.min.y <= centre.y + h && light.min.z <= c.farDepth;
}

// The box's farthest point from the centre lies within the radius.
bool insideSphere(const Bounds& box, glm::vec3 centre, float radius)
{
    const glm::vec3 farthest = glm::max(glm::abs(box.min - centre), glm::abs(box.max - centre));
    return glm::dot(farthest, farthest) <= radius * radius;
}

// The culling loop of either fit: `heldByPrevious` says whether the previous cascade already holds a caster's shadow.
template <typename HeldByPrevious>
CasterCullingResult cullCasters(const DirectionalShadowCascade& cascade, const LightSpaceCasters& casters,
                                HeldByPrevious heldByPrevious)
{
    CasterCullingResult result;
    for (std::uint32_t i = 0; i < casters.light.size(); ++i) {
        if (!overlapsCascade(casters.light[i], cascade))
            continue;
        ++result.overlapping;
        if (heldByPrevious(casters.world[i])) {
            ++result.culledByBias;
            continue;
        }
        result.casters.push_back(i);
    }
    return result;
}

} // namespace

float cascadeBlendCullingFactor(float cascadeFade) { return std::max(0.0f, 0.8f - cascadeFade); }

CasterCullingResult cullShadowCasters(const DirectionalShadowCascade& cascade, const LightSpaceCasters& casters,
                                      const std::optional<Sphere>& previousCullingSphere, float cullingFactor)
{
    return cullCasters(cascade, casters, [&](const Bounds& caster) {
        return previousCullingSphere &&
               insideSphere(caster, previousCullingSphere->centre, previousCullingSphere->radius * cullingFactor);
    });
}

bool castersInReach(const LightSpaceCasters& casters, std::span<const Sphere> cullingSpheres)
{
    // A stable fit's square is the sphere's, snapped by under a texel; a close fit's lies inside the sphere.
    constexpr float kSnapMargin = 1.05f;
    for (const Sphere& sphere : cullingSpheres) {
        const glm::vec3 centre = casters.basis.toLight(sphere.centre);
        const float reach = sphere.radius * kSnapMargin;
        for (const Bounds& caster : casters.light)
            if (caster.min.x <= centre.x + reach && caster.max.x >= centre.x - reach &&
                caster.min.y <= centre.y + reach && caster.max.y >= centre.y - reach &&
                caster.min.z <= centre.z + reach)
                return true;
    }
    return false;
}

bool insideFrustumSlice(const Bounds& box, const FrustumSlice& slice, float depthFactor)
{
    const ShadowCamera& camera = slice.camera;
    const glm::vec3 right = glm::cross(camera.forward, camera.up);
    const float tanY = std::tan(0.5f * camera.fovY);
    const float tanX = tanY * camera.aspect;
    const float farDistance = slice.nearDistance + (slice.farDistance - slice.nearDistance) * depthFactor;
    for (const glm::vec3& corner : box.corners()) {
        const glm::vec3 offset = corner - camera.position;
        const float depth = glm::dot(offset, camera.forward);
        if (depth < slice.nearDistance || depth > farDistance || std::abs(glm::dot(offset, right)) > depth * tanX ||
            std::abs(glm::dot(offset, camera.up)) > depth * tanY)
            return false;
    }
    return true;
}

CasterCullingResult cullCloseFitShadowCasters(const DirectionalShadowCascade& cascade, const LightSpaceCasters& casters,
                                              const std::optional<FrustumSlice>& previousSlice, float cullingFactor)
{
    return cullCasters(cascade, casters, [&](const Bounds& caster) {
        return previousSlice && insideFrustumSlice(caster, *previousSlice, cullingFactor);
    });
}

} // namespace penumbra::shadows
