#pragma once

#include "penumbra/shadows/ShadowSettings.hpp"

#include <glm/vec4.hpp>

namespace penumbra::shadows {

// (1 / maxDistance, 1 / distanceFade, 1 / (1 - (1 - cascadeFade)^2), 1 / cascadeFade): the lit shader's
// reciprocals for fadedShadowStrength. The stable fit's cascade fade is taken on squared distance (the
// selection already has it), so the fraction f becomes 1 - (1 - f)^2 to keep the same fade band; the close fit's
// on view depth, linear like the distance fade.
glm::vec4 shadowDistanceFade(const ShadowSettings& settings);

// saturate((1 - distance * scale) * fade): 1 inside, falling linearly to 0 at distance = 1 / scale.
float fadedShadowStrength(float distance, float scale, float fade);

} // namespace penumbra::shadows
