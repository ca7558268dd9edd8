#pragma once

#include <glm/vec3.hpp>

#include <optional>

namespace penumbra::render {

// The light every surface gets besides the scene's lights, scaled by the material's occlusion: the same from
// every side, or a sky/ground hemisphere (`color` from above, `ground` from below, blended by the normal's
// height: 0.5 + 0.5 n.y of the sky).
struct AmbientLight {
    glm::vec3 color{1.0f}; // linear RGB, the sky's with a hemisphere
    float intensity = 0.03f;
    std::optional<glm::vec3> ground; // linear RGB from below; none: `color` from every side

    // Linear radiance from above (from every side without `ground`).
    glm::vec3 sky() const { return color * intensity; }
    // Linear radiance from below.
    glm::vec3 below() const { return ground.value_or(color) * intensity; }
};

// Upper bound of AmbientLight::intensity: well above any scene's sun, so a typo is caught.
inline constexpr float kMaxAmbientIntensity = 100.0f;

// Throws rhi::Error naming the field ("ambient.color", "ambient.intensity", "ambient.ground") and the allowed
// range for a component below 0 or not finite, or an intensity outside [0, kMaxAmbientIntensity].
void validate(const AmbientLight& ambient);

} // namespace penumbra::render
