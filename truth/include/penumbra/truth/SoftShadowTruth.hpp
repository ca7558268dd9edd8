#pragma once

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/scene/AreaLightTruth.hpp"

namespace penumbra::render {

// What soft shadows need of a light against the area-light ray cast (scene::AreaLightTruth).

// The filter the plans gave the light's shadow map (its own, or the atlas's). Throws rhi::Error for a light
// without one.
shadows::ShadowFilter plannedShadowFilter(const ShadowPlans& plans, const scene::LightRef& light);

// The light's source size: degrees of angular diameter (directional) or world units of radius (spot, point).
float lightSourceSize(const scene::Scene& scene, const scene::LightRef& light);

scene::AreaLightSource areaLightOf(const scene::Scene& scene, const scene::LightRef& light);

} // namespace penumbra::render
