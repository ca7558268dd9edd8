#include "penumbra/shadows/CasterCulling.hpp"

#include <algorithm>
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

} // namespace

float cascadeBlendCullingFactor(float cascadeFade) { return std::max(0.0f, 0.8f - cascadeFade); }

CasterCullingResult cullShadowCasters(const DirectionalShadowCascade& cascade, std::span<const Bounds> casterBounds,
                                      const std::optional<Sphere>& previousCullingSphere, float cullingFactor)
{
    CasterCullingResult result;
    for (std::uint32_t i = 0; i < casterBounds.size(); ++i) {
        const Bounds& caster = casterBounds[i];
        if (!overlapsCascade(lightSpaceBounds(cascade.basis, caster), cascade))
            continue;
        ++result.overlapping;
        if (previousCullingSphere &&
            insideSphere(caster, previousCullingSphere->centre, previousCullingSphere->radius * cullingFactor)) {
            ++result.culledByBias;
            continue;
        }
        result.casters.push_back(i);
    }
    return result;
}

} // namespace penumbra::shadows
