#include "penumbra/scene/Light.hpp"

#include <cmath>

namespace penumbra::scene {

const char* lightKindName(LightKind kind)
{
    switch (kind) {
    case LightKind::Directional:
        return "directional light";
    case LightKind::Spot:
        return "spot light";
    case LightKind::Point:
        return "point light";
    }
    return "light";
}

glm::vec3 lightDirection(float pitch, float yaw)
{
    const float horizontal = std::cos(pitch);
    return {horizontal * std::sin(yaw), -std::sin(pitch), horizontal * std::cos(yaw)};
}

} // namespace penumbra::scene
