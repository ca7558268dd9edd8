#include "ShadowInputs.hpp"

#include <algorithm>
#include <glm/geometric.hpp>

namespace penumbra::render {
namespace {

// A light's brightness for its shadow's importance: its intensity times its colour's largest channel.
float brightness(glm::vec3 color, float intensity) { return intensity * std::max({color.r, color.g, color.b}); }

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
                          .filter = light.shadowFilter,
                          .angularDiameter = light.angularDiameter,
                          .normalBiasSide = light.normalBiasSide,
                          .staticUpdate = light.shadowUpdate});
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
                          .filter = l.shadowFilter,
                          .sourceRadius = l.sourceRadius,
                          .normalBiasSide = l.normalBiasSide,
                          .staticUpdate = l.shadowUpdate,
                          .intensity = brightness(l.color, l.intensity),
                          .shadowResolution = l.shadowResolution});
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
                          .filter = l.shadowFilter,
                          .sourceRadius = l.sourceRadius,
                          .normalBiasSide = l.normalBiasSide,
                          .staticUpdate = l.shadowUpdate,
                          .intensity = brightness(l.color, l.intensity),
                          .shadowResolution = l.shadowResolution});
    return inputs;
}

} // namespace penumbra::render
