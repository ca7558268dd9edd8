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

std::string_view normalBiasSideName(NormalBiasSide side)
{
    return side == NormalBiasSide::Caster ? "caster" : "receiver";
}

std::optional<NormalBiasSide> parseNormalBiasSide(std::string_view name)
{
    if (name == "receiver")
        return NormalBiasSide::Receiver;
    if (name == "caster")
        return NormalBiasSide::Caster;
    return std::nullopt;
}

glm::vec3 lightDirection(float pitch, float yaw)
{
    const float horizontal = std::cos(pitch);
    return {horizontal * std::sin(yaw), -std::sin(pitch), horizontal * std::cos(yaw)};
}

} // namespace penumbra::scene
