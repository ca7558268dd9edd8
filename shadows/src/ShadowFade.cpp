#include "penumbra/shadows/ShadowFade.hpp"

#include <algorithm>

namespace penumbra::shadows {

ShadowDistanceFade shadowDistanceFade(const ShadowSettings& settings)
{
    const float f = 1.0f - settings.directional.cascadeFade;
    return {.inverseMaxDistance = 1.0f / settings.maxDistance,
            .inverseDistanceFade = 1.0f / settings.distanceFade,
            .inverseSphereCascadeFade = 1.0f / (1.0f - f * f),
            .inverseDepthCascadeFade = 1.0f / settings.directional.cascadeFade};
}

float fadedShadowStrength(float distance, float scale, float fade)
{
    return std::clamp((1.0f - distance * scale) * fade, 0.0f, 1.0f);
}

} // namespace penumbra::shadows
