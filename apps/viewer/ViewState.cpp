#include "ViewState.hpp"

#include <glm/geometric.hpp>

namespace penumbra::viewer {

std::string applyViewState(const ViewState& edited, ViewState& applied, scene::Scene& scene)
{
    ViewState candidate = edited;
    for (scene::DirectionalLight& light : candidate.lights)
        light.direction = glm::normalize(light.direction); // a zero vector turns NaN and fails validation
    const std::vector<scene::DirectionalLight> previous = scene.lights;
    try {
        shadows::validate(candidate.shadows);
        scene.lights = candidate.lights;
        scene.validate();
    } catch (const std::exception& e) {
        scene.lights = previous;
        return e.what();
    }
    applied = std::move(candidate);
    return {};
}

} // namespace penumbra::viewer
