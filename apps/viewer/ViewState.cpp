#include "ViewState.hpp"

#include <glm/geometric.hpp>

namespace penumbra::viewer {

std::string applyViewState(const ViewState& edited, ViewState& applied, scene::Scene& scene)
{
    ViewState candidate = edited;
    // A zero vector turns NaN and fails validation.
    for (scene::DirectionalLight& light : candidate.lights)
        light.direction = glm::normalize(light.direction);
    for (scene::SpotLight& light : candidate.spotLights)
        light.direction = glm::normalize(light.direction);
    const auto previous = std::make_tuple(scene.lights, scene.spotLights, scene.pointLights);
    try {
        shadows::validate(candidate.shadows);
        scene.lights = candidate.lights;
        scene.spotLights = candidate.spotLights;
        scene.pointLights = candidate.pointLights;
        scene.validate();
    } catch (const std::exception& e) {
        std::tie(scene.lights, scene.spotLights, scene.pointLights) = previous;
        return e.what();
    }
    for (std::size_t i = 0; i < scene.objects.size() && i < candidate.objects.size(); ++i) {
        scene.objects[i].castShadows = candidate.objects[i].cast;
        scene.objects[i].receiveShadows = candidate.objects[i].receive;
        scene.objects[i].mobility = candidate.objects[i].mobility;
    }
    ++scene.revision;
    applied = std::move(candidate);
    return {};
}

ViewState viewStateOf(const scene::Scene& scene)
{
    ViewState state;
    state.lights = scene.lights;
    state.spotLights = scene.spotLights;
    state.pointLights = scene.pointLights;
    for (const scene::Object& object : scene.objects)
        state.objects.push_back({object.castShadows, object.receiveShadows, object.mobility});
    return state;
}

} // namespace penumbra::viewer
