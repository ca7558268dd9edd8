#include "penumbra/truth/SoftShadowTruth.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::truth {

shadows::ShadowFilter plannedShadowFilter(const render::ShadowPlans& plans, const scene::LightRef& light)
{
    const auto noShadow = [&] {
        return rhi::Error(
            fmt::format("{} {} has no shadow map in this frame", scene::lightKindName(light.kind), light.index));
    };
    switch (light.kind) {
    case scene::LightKind::Directional: {
        const int slot =
            light.index < plans.directional.shadowSlots.size() ? plans.directional.shadowSlots[light.index] : -1;
        if (slot < 0)
            throw noShadow();
        return plans.directional.lights[std::size_t(slot)].filter;
    }
    case scene::LightKind::Spot: {
        const int tile = light.index < plans.local.spotTiles.size() ? plans.local.spotTiles[light.index] : -1;
        if (tile < 0)
            throw noShadow();
        return static_cast<shadows::ShadowFilter>(plans.local.tileData.at(std::size_t(tile)).shadowFilter);
    }
    case scene::LightKind::Point: {
        const int shadow = light.index < plans.local.pointShadows.size() ? plans.local.pointShadows[light.index] : -1;
        if (shadow < 0)
            throw noShadow();
        if (plans.local.cubes.empty())
            return static_cast<shadows::ShadowFilter>(plans.local.tileData.at(std::size_t(shadow)).shadowFilter);
        return static_cast<shadows::ShadowFilter>(plans.local.uniforms.cubes[std::size_t(shadow)].shadowFilter);
    }
    }
    throw noShadow();
}

float lightSourceSize(const scene::Scene& scene, const scene::LightRef& light)
{
    switch (light.kind) {
    case scene::LightKind::Directional:
        return scene.lights.at(light.index).angularDiameter;
    case scene::LightKind::Spot:
        return scene.spotLights.at(light.index).sourceRadius;
    case scene::LightKind::Point:
        return scene.pointLights.at(light.index).sourceRadius;
    }
    return 0.0f;
}

AreaLightSource areaLightOf(const scene::Scene& scene, const scene::LightRef& light)
{
    switch (light.kind) {
    case scene::LightKind::Directional:
        return areaLightOf(scene.lights.at(light.index));
    case scene::LightKind::Spot:
        return areaLightOf(scene.spotLights.at(light.index));
    case scene::LightKind::Point:
        return areaLightOf(scene.pointLights.at(light.index));
    }
    return {};
}

} // namespace penumbra::truth
