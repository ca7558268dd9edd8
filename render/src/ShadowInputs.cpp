#include "ShadowInputs.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace penumbra::render {
namespace {

shadows::NormalBiasSide biasSide(scene::NormalBiasSide side)
{
    return side == scene::NormalBiasSide::Caster ? shadows::NormalBiasSide::Caster : shadows::NormalBiasSide::Receiver;
}

// A scene light's shadow filter: nullopt for the atlas's, else a shadows::ShadowFilter.
std::optional<shadows::ShadowFilter> lightFilter(std::int32_t filter, const std::string& what)
{
    if (filter == scene::kAtlasShadowFilter)
        return std::nullopt;
    if (filter < 0 || filter >= shadows::kShadowFilterCount)
        throw rhi::Error(fmt::format("{}: shadowFilter {} is out of range, allowed {} (the atlas's) or 0..{} ({})",
                                     what, filter, scene::kAtlasShadowFilter, shadows::kShadowFilterCount - 1,
                                     shadows::filterCommandNames()));
    return static_cast<shadows::ShadowFilter>(filter);
}

// A scene light's static shadow map mode: nullopt for the settings'.
std::optional<shadows::StaticShadowUpdate> staticUpdate(scene::ShadowUpdate update)
{
    switch (update) {
    case scene::ShadowUpdate::EveryFrame:
        return shadows::StaticShadowUpdate::EveryFrame;
    case scene::ShadowUpdate::OnChange:
        return shadows::StaticShadowUpdate::OnChange;
    case scene::ShadowUpdate::OnDemand:
        return shadows::StaticShadowUpdate::OnDemand;
    case scene::ShadowUpdate::Settings:
        break;
    }
    return std::nullopt;
}

} // namespace

shadows::ShadowCamera shadowCamera(const scene::Camera& camera, float aspect)
{
    const glm::vec3 up = glm::normalize(glm::cross(camera.right(), camera.forward));
    return {camera.position, camera.forward, up, camera.fovY, aspect, camera.nearPlane, camera.farPlane};
}

std::vector<shadows::DirectionalShadowLightInput> shadowLights(const std::vector<scene::DirectionalLight>& lights)
{
    std::vector<shadows::DirectionalShadowLightInput> inputs;
    for (const scene::DirectionalLight& light : lights)
        inputs.push_back({.direction = light.direction,
                          .strength = light.shadowStrength,
                          .nearPlaneOffset = light.nearPlaneOffset,
                          .normalBias = light.normalBias,
                          .slopeScaleBias = light.slopeScaleBias,
                          .castsShadows = true,
                          .filter = lightFilter(light.shadowFilter, "light '" + light.name + "'"),
                          .angularDiameter = light.angularDiameter,
                          .normalBiasSide = biasSide(light.normalBiasSide),
                          .staticUpdate = staticUpdate(light.shadowUpdate)});
    return inputs;
}

std::vector<shadows::SpotShadowInput> spotShadowInputs(const std::vector<scene::SpotLight>& lights)
{
    std::vector<shadows::SpotShadowInput> inputs;
    for (const scene::SpotLight& l : lights)
        inputs.push_back({.position = l.position,
                          .direction = l.direction,
                          .range = l.range,
                          .outerAngle = l.outerAngle,
                          .strength = l.shadowStrength,
                          .normalBias = l.normalBias,
                          .slopeScaleBias = l.slopeScaleBias,
                          .nearPlane = l.shadowNearPlane,
                          .filter = lightFilter(l.shadowFilter, "spot light '" + l.name + "'"),
                          .sourceRadius = l.sourceRadius,
                          .normalBiasSide = biasSide(l.normalBiasSide),
                          .staticUpdate = staticUpdate(l.shadowUpdate)});
    return inputs;
}

std::vector<shadows::PointShadowInput> pointShadowInputs(const std::vector<scene::PointLight>& lights)
{
    std::vector<shadows::PointShadowInput> inputs;
    for (const scene::PointLight& l : lights)
        inputs.push_back({.position = l.position,
                          .range = l.range,
                          .strength = l.shadowStrength,
                          .normalBias = l.normalBias,
                          .slopeScaleBias = l.slopeScaleBias,
                          .nearPlane = l.shadowNearPlane,
                          .filter = lightFilter(l.shadowFilter, "point light '" + l.name + "'"),
                          .sourceRadius = l.sourceRadius,
                          .normalBiasSide = biasSide(l.normalBiasSide),
                          .staticUpdate = staticUpdate(l.shadowUpdate)});
    return inputs;
}

} // namespace penumbra::render
