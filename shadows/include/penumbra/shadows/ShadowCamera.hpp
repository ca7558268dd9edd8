#pragma once

#include <glm/vec3.hpp>

namespace penumbra::shadows {

// The viewing camera as shadow planning needs it: a perspective camera in world space.
struct ShadowCamera {
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f}; // unit
    glm::vec3 up{0.0f, 1.0f, 0.0f}; // unit, orthogonal to forward
    float fovY = 1.0f; // vertical field of view, radians
    float aspect = 1.0f; // width / height
    float nearPlane = 0.1f;
    float farPlane = 1000.0f;
};

} // namespace penumbra::shadows
