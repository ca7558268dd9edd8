#pragma once

#include "penumbra/scene/Scene.hpp"

#include <optional>
#include <string>

namespace penumbra::apps {

// --filter and --light-size applied to every light of `scene`: `filter` a shadows::filterFromCommandName name (empty:
// each light keeps its own), `lightSize` degrees of angular diameter for directional lights and world units of radius
// for spot and point lights. Throws rhi::Error for an unknown filter, scene::SceneError for a size out of a light's
// range.
void applyLightOverrides(scene::Scene& scene, const std::string& filter, std::optional<float> lightSize);

} // namespace penumbra::apps
