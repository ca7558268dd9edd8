#include "LightOverrides.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <fmt/format.h>

namespace penumbra::apps {

void applyLightOverrides(scene::Scene& scene, const std::string& filter, std::optional<float> lightSize)
{
    if (!filter.empty()) {
        const std::optional<shadows::ShadowFilter> chosen = shadows::filterFromCommandName(filter);
        if (!chosen)
            throw rhi::Error(fmt::format("--filter '{}' is not one of {}", filter, shadows::filterCommandNames()));
        const auto value = static_cast<std::int32_t>(*chosen);
        for (scene::DirectionalLight& light : scene.lights)
            light.shadowFilter = value;
        for (scene::SpotLight& light : scene.spotLights)
            light.shadowFilter = value;
        for (scene::PointLight& light : scene.pointLights)
            light.shadowFilter = value;
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
