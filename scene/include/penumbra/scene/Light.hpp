#pragma once

#include <glm/vec3.hpp>

#include <string>

namespace penumbra::scene {

struct DirectionalLight {
    std::string name;
    glm::vec3 color{1.0f}; // linear RGB
    float intensity = 1.0f;
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // unit, from the light INTO the scene; surfaces are lit from -direction
    float shadowStrength = 1.0f;            // 0: shadows ignored, 1: fully dark
    float slopeScaleBias = 1.0f;            // the RHI's depth-bias slope factor for this light's casters
    float normalBias = 1.0f;                // receiver offset along its normal, in units of the cascade's filter-sized texel diagonal
    float nearPlaneOffset = 0.2f;           // pulls the shadow projection's near plane back, in world units
};

// Unit light direction for a light pitched `pitch` radians below the horizon and turned
// `yaw` radians about +y, measured from +z towards +x (yaw 0 shines towards +z).
// The seeds set lights up the same way (X rotation, then Y rotation).
glm::vec3 lightDirection(float pitch, float yaw);

} // namespace penumbra::scene
