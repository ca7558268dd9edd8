#include "penumbra/shadows/CasterCulling.hpp"

#include <algorithm>
#include <glm/geometric.hpp>

namespace penumbra::shadows {
namespace {

// The culling loop of either fit over the volume's two rules: the light box, then the culling bias.
CasterCullingResult cullCasters(const CasterVolume& volume, const LightSpaceCasters& casters)
{
    CasterCullingResult result;
    for (std::uint32_t i = 0; i < casters.light.size(); ++i) {
        if (!overlapsCascade(casters.light[i], volume))
            continue;
        ++result.overlapping;
        if (heldByPrevious(casters.world[i], volume)) {
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
    return cullCasters(cascadeVolume(cascade, previousCullingSphere, cullingFactor), casters);
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
    return heldByPrevious(box, closeCascadeVolume(DirectionalShadowCascade{}, slice, depthFactor));
}

CasterCullingResult cullCloseFitShadowCasters(const DirectionalShadowCascade& cascade, const LightSpaceCasters& casters,
                                              const std::optional<FrustumSlice>& previousSlice, float cullingFactor)
{
    return cullCasters(closeCascadeVolume(cascade, previousSlice, cullingFactor), casters);
}

} // namespace penumbra::shadows
