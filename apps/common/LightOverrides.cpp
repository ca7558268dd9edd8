#include "LightOverrides.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <fmt/format.h>

namespace penumbra::apps {

namespace {

// `set` on every directional, spot and point light: what the three kinds have in common.
template <typename Set>
void forEveryLight(scene::Scene& scene, const Set& set)
{
    for (scene::DirectionalLight& light : scene.lights)
        set(light);
    for (scene::SpotLight& light : scene.spotLights)
        set(light);
    for (scene::PointLight& light : scene.pointLights)
        set(light);
}

} // namespace

void applyLightOverrides(scene::Scene& scene, const std::string& filter, std::optional<float> lightSize,
                         const std::string& normalBiasSide)
{
    if (!filter.empty()) {
        const std::optional<shadows::ShadowFilter> chosen = shadows::filterFromCommandName(filter);
        if (!chosen)
            throw rhi::Error(fmt::format("--filter '{}' is not one of {}", filter, shadows::filterCommandNames()));
        forEveryLight(scene, [value = static_cast<std::int32_t>(*chosen)](auto& light) { light.shadowFilter = value; });
    }
    if (!normalBiasSide.empty()) {
        const std::optional<scene::NormalBiasSide> side = scene::parseNormalBiasSide(normalBiasSide);
        if (!side)
            throw rhi::Error(fmt::format("--normal-bias-side '{}' is not receiver or caster", normalBiasSide));
        forEveryLight(scene, [side = *side](auto& light) { light.normalBiasSide = side; });
    }
    if (lightSize) {
        for (scene::DirectionalLight& light : scene.lights)
            light.angularDiameter = *lightSize;
        for (scene::SpotLight& light : scene.spotLights)
            light.sourceRadius = *lightSize;
        for (scene::PointLight& light : scene.pointLights)
            light.sourceRadius = *lightSize;
    }
    if (!filter.empty() || lightSize)
        scene.validate();
}

} // namespace penumbra::apps
