#include "penumbra/shadows/ShadowFade.hpp"

#include <algorithm>

namespace penumbra::shadows {

glm::vec4 shadowDistanceFade(const ShadowSettings& settings)
{
    const float f = 1.0f - settings.directional.cascadeFade;
    return {1.0f / settings.maxDistance, 1.0f / settings.distanceFade, 1.0f / (1.0f - f * f),
            1.0f / settings.directional.cascadeFade};
}

float fadedShadowStrength(float distance, float scale, float fade)
{
    return std::clamp((1.0f - distance * scale) * fade, 0.0f, 1.0f);
}

} // namespace penumbra::shadows
