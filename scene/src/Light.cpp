#include "penumbra/scene/Light.hpp"

#include <cmath>

namespace penumbra::scene {

glm::vec3 lightDirection(float pitch, float yaw)
{
    const float horizontal = std::cos(pitch);
    return {horizontal * std::sin(yaw), -std::sin(pitch), horizontal * std::cos(yaw)};
}

} // namespace penumbra::scene
