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

// Each mode a light can have with its name: "settings" (none of its own), then StaticShadowUpdate's values.
struct NamedUpdate {
    LightShadowUpdate update;
    std::string_view name;
};
constexpr std::array<NamedUpdate, 4> kUpdates{{{std::nullopt, "settings"},
                                               {StaticShadowUpdate::EveryFrame, "everyFrame"},
                                               {StaticShadowUpdate::OnChange, "onChange"},
                                               {StaticShadowUpdate::OnDemand, "onDemand"}}};

} // namespace

std::optional<LightShadowUpdate> parseLightShadowUpdate(std::string_view name)
{
    for (const NamedUpdate& u : kUpdates)
        if (u.name == name)
            return u.update;
    return std::nullopt;
}

glm::vec3 lightDirection(float pitch, float yaw)
{
    const float horizontal = std::cos(pitch);
    return {horizontal * std::sin(yaw), -std::sin(pitch), horizontal * std::cos(yaw)};
}

} // namespace penumbra::scene
