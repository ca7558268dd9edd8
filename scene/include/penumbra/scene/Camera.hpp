#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace penumbra::scene {

// Perspective camera. The projection itself belongs to the renderer, which builds it for
// its depth convention (rhi::Conventions::perspective) from fovY, the image's aspect and
// the near and far planes here.
struct Camera {
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f}; // unit
    glm::vec3 up{0.0f, 1.0f, 0.0f}; // need not be orthogonal to forward, must not be parallel
    float fovY = 1.0471976f; // vertical field of view, radians (60 degrees)
    float nearPlane = 0.1f;
    float farPlane = 200.0f;

    // Right-handed world-to-view matrix: the camera looks down view -z, +y up.
    glm::mat4 view() const;
    // Unit right vector of the view (view +x in world space).
    glm::vec3 right() const;
};

Camera lookAt(const glm::vec3& eye, const glm::vec3& target, float fovY, const glm::vec3& up = {0.0f, 1.0f, 0.0f});

} // namespace penumbra::scene
