#include "LightOverrides.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <exception>
#include <fmt/format.h>
#include <optional>
#include <utility>

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

// NAME and MODE of a NAME=MODE spec (the last '=' splits: light names may hold one).
std::optional<std::pair<std::string, scene::LightShadowUpdate>> parseLightShadowUpdate(const std::string& spec)
{
    const std::size_t split = spec.rfind('=');
    if (split == std::string::npos || split == 0)
        return std::nullopt;
    const std::optional<scene::LightShadowUpdate> update =
        scene::parseLightShadowUpdate(std::string_view(spec).substr(split + 1));
    if (!update)
        return std::nullopt;
    return std::pair{spec.substr(0, split), *update};
}

// NAME and N of a NAME=N spec (the last '=' splits), N a number of texels in the allowed range.
std::optional<std::pair<std::string, float>> parseLightShadowResolution(const std::string& spec)
{
    const std::size_t split = spec.rfind('=');
    if (split == std::string::npos || split == 0)
        return std::nullopt;
    try {
        std::size_t used = 0;
        const std::string number = spec.substr(split + 1);
        const float texels = std::stof(number, &used);
        if (used != number.size() || !(texels >= scene::kMinShadowResolution && texels <= scene::kMaxShadowResolution))
            return std::nullopt;
        return std::pair{spec.substr(0, split), texels};
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

// --light-size against each light's allowed range, so the error names the flag as typed rather than the light's
// field that scene::Scene::validate would name.
void checkLightSize(const scene::Scene& scene, float size)
{
    if (!(size >= 0.0f))
        throw rhi::Error(fmt::format("--light-size {}: a source size is at least 0", size));
    if (!scene.lights.empty() && size > scene::kMaxAngularDiameter)
        throw rhi::Error(fmt::format("--light-size {}: directional lights take 0 to {} degrees of angular diameter "
                                     "(light '{}')",
                                     size, scene::kMaxAngularDiameter, scene.lights.front().name));
    const auto checkLocal = [size](const auto& light, const char* kind) {
        if (size > light.range)
            throw rhi::Error(fmt::format("--light-size {}: spot and point lights take a radius of 0 to their range "
                                         "in world units ({} light '{}' has range {})",
                                         size, kind, light.name, light.range));
    };
    for (const scene::SpotLight& light : scene.spotLights)
        checkLocal(light, "spot");
    for (const scene::PointLight& light : scene.pointLights)
        checkLocal(light, "point");
}

} // namespace

bool isLightShadowUpdate(const std::string& spec) { return parseLightShadowUpdate(spec).has_value(); }

void applyLightShadowUpdate(scene::Scene& scene, const std::string& spec)
{
    const auto parsed = parseLightShadowUpdate(spec);
    if (!parsed)
        throw rhi::Error(fmt::format("--light-static-map '{}' is not NAME=MODE with MODE one of {}", spec,
                                     scene::kLightShadowUpdateNames));
    bool found = false;
    forEveryLight(scene, [&](auto& light) {
        if (light.name == parsed->first) {
            light.shadowUpdate = parsed->second;
            found = true;
        }
    });
    if (!found)
        throw rhi::Error(
            fmt::format("--light-static-map '{}': the scene has no light named '{}'", spec, parsed->first));
}

bool isLightShadowResolution(const std::string& spec) { return parseLightShadowResolution(spec).has_value(); }

void applyLightShadowResolution(scene::Scene& scene, const std::string& spec)
{
    const auto parsed = parseLightShadowResolution(spec);
    if (!parsed)
        throw rhi::Error(fmt::format("--light-shadow-resolution '{}' is not NAME=N with N texels from {} to {}", spec,
                                     scene::kMinShadowResolution, scene::kMaxShadowResolution));
    bool found = false;
    const auto set = [&](auto& light) {
        if (light.name == parsed->first) {
            light.shadowResolution = parsed->second;
            found = true;
        }
    };
    for (scene::SpotLight& light : scene.spotLights)
        set(light);
    for (scene::PointLight& light : scene.pointLights)
        set(light);
    if (!found)
        throw rhi::Error(fmt::format("--light-shadow-resolution '{}': the scene has no spot or point light named '{}'",
                                     spec, parsed->first));
}

void applyLightOverrides(scene::Scene& scene, const std::string& filter, std::optional<float> lightSize,
                         const std::string& normalBiasSide)
{
    if (!filter.empty()) {
        const std::optional<shadows::ShadowFilter> chosen = shadows::filterFromCommandName(filter);
        if (!chosen)
            throw rhi::Error(fmt::format("--filter '{}' is not one of {}", filter, shadows::filterCommandNames()));
        forEveryLight(scene, [value = *chosen](auto& light) { light.shadowFilter = value; });
    }
    if (!normalBiasSide.empty()) {
        const std::optional<scene::NormalBiasSide> side = scene::parseNormalBiasSide(normalBiasSide);
        if (!side)
            throw rhi::Error(fmt::format("--normal-bias-side '{}' is not receiver or caster", normalBiasSide));
        forEveryLight(scene, [side = *side](auto& light) { light.normalBiasSide = side; });
    }
    if (lightSize) {
        checkLightSize(scene, *lightSize);
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
