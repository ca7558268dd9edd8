#include "penumbra/scene/Light.hpp"

#include <array>
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

namespace {

constexpr std::array<std::string_view, 4> kUpdateNames{"settings", "everyFrame", "onChange", "onDemand"};

} // namespace

std::string_view shadowUpdateName(ShadowUpdate update) { return kUpdateNames.at(static_cast<std::size_t>(update)); }

std::optional<ShadowUpdate> parseShadowUpdate(std::string_view name)
{
    for (std::size_t i = 0; i < kUpdateNames.size(); ++i)
        if (kUpdateNames[i] == name)
            return static_cast<ShadowUpdate>(i);
    return std::nullopt;
}

glm::vec3 lightDirection(float pitch, float yaw)
{
    const float horizontal = std::cos(pitch);
    return {horizontal * std::sin(yaw), -std::sin(pitch), horizontal * std::cos(yaw)};
}

} // namespace penumbra::scene
