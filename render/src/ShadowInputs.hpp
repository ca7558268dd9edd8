#pragma once

#include "penumbra/scene/Camera.hpp"
#include "penumbra/scene/Light.hpp"
#include "penumbra/shadows/DirectionalShadowPlanner.hpp"
#include "penumbra/shadows/LocalShadowPlanner.hpp"
#include "penumbra/shadows/ShadowCamera.hpp"

#include <vector>

// The scene's lights as the shadow planners take them.
namespace penumbra::render {

shadows::ShadowCamera shadowCamera(const scene::Camera& camera, float aspect);
// The lights' shadow options pass through as they are: the scene and the planners share one vocabulary.
std::vector<shadows::DirectionalShadowLightInput> shadowLights(const std::vector<scene::DirectionalLight>& lights);
std::vector<shadows::SpotShadowInput> spotShadowInputs(const std::vector<scene::SpotLight>& lights);
std::vector<shadows::PointShadowInput> pointShadowInputs(const std::vector<scene::PointLight>& lights);

} // namespace penumbra::render
