#include "ShadowInputs.hpp"

#include <glm/geometric.hpp>

namespace penumbra::render {
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
                          .staticUpdate = l.shadowUpdate});
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
                          .staticUpdate = l.shadowUpdate});
    return inputs;
}

} // namespace penumbra::render
