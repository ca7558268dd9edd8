#pragma once

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/truth/AreaLightTruth.hpp"

namespace penumbra::truth {

// What soft shadows need of a light against the area-light ray cast (truth::AreaLightTruth).

// The filter the plans gave the light's shadow map (its own, or the atlas's). Throws rhi::Error for a light
// without one.
shadows::ShadowFilter plannedShadowFilter(const render::ShadowPlans& plans, const scene::LightRef& light);

// The light's source size: degrees of angular diameter (directional) or world units of radius (spot, point).
float lightSourceSize(const scene::Scene& scene, const scene::LightRef& light);

AreaLightSource areaLightOf(const scene::Scene& scene, const scene::LightRef& light);

} // namespace penumbra::truth
