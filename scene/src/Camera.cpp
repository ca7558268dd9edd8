#include "penumbra/scene/Camera.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::scene {

glm::mat4 Camera::view() const { return glm::lookAtRH(position, position + forward, up); }

glm::vec3 Camera::right() const { return glm::normalize(glm::cross(forward, up)); }

Camera lookAt(const glm::vec3& eye, const glm::vec3& target, float fovY, const glm::vec3& up)
{
    return {.position = eye, .forward = glm::normalize(target - eye), .up = up, .fovY = fovY};
}

} // namespace penumbra::scene
