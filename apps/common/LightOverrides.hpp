#pragma once

#include "penumbra/scene/Scene.hpp"

#include <optional>
#include <string>

namespace penumbra::apps {

// --filter, --light-size and --normal-bias-side applied to every light of `scene`: `filter` a
// shadows::filterFromCommandName name (empty: each light keeps its own), `lightSize` degrees of angular diameter for
// directional lights and world units of radius for spot and point lights, `normalBiasSide` "receiver" or "caster"
// (empty: each light's own). Throws rhi::Error for an unknown filter or side, scene::SceneError for a size out of a
// light's range.
void applyLightOverrides(scene::Scene& scene, const std::string& filter, std::optional<float> lightSize,
                         const std::string& normalBiasSide = {});

// --light-static-map NAME=MODE: the light named NAME (directional, spot or point; every light of that name) draws
// its static shadow map in scene::LightShadowUpdate MODE ("settings", "everyFrame", "onChange", "onDemand"). Throws
// rhi::Error naming the option for a malformed spec, an unknown mode or a name no light has.
void applyLightShadowUpdate(scene::Scene& scene, const std::string& spec);
// Whether `spec` has the NAME=MODE form with a known MODE: the option's check.
bool isLightShadowUpdate(const std::string& spec);

// --light-shadow-resolution NAME=N: the spot and point lights named NAME ask for shadow tiles of N texels per side
// (scene::SpotLight::shadowResolution). Throws rhi::Error naming the option for a malformed spec, N outside
// scene::kMinShadowResolution..kMaxShadowResolution, or a name no spot or point light has.
void applyLightShadowResolution(scene::Scene& scene, const std::string& spec);
// Whether `spec` has the NAME=N form with N in range: the option's check.
bool isLightShadowResolution(const std::string& spec);

} // namespace penumbra::apps
