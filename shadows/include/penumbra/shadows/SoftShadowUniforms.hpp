#pragma once

#include "penumbra/shadows/ShadowSettings.hpp"

#include <glm/vec4.hpp>

namespace penumbra::shadows {

// SoftShadowSettings as the lit shader's blocks carry them (two vec4s, std140).
struct SoftShadowUniforms {
    glm::vec4 scales{0.0f}; // blockerSearchScale, penumbraScale, minPenumbraTexels, maxPenumbraTexels
    glm::vec4 counts{0.0f}; // blockerSamples, filterSamples, poissonRadiusTexels, 0
};
static_assert(sizeof(SoftShadowUniforms) == 32);

SoftShadowUniforms softShadowUniforms(const SoftShadowSettings& soft);

// tan of half a directional light's angular diameter (degrees).
float tanHalfAngularDiameter(float degrees);

} // namespace penumbra::shadows
