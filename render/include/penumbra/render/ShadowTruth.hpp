#pragma once

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/Light.hpp"
#include "penumbra/scene/TruthComparison.hpp"

#include <glm/vec3.hpp>

namespace penumbra::render {

// What the renderer's shadow maps say against a CPU ray cast (scene::GroundTruth), per light.

// The visibility view (FrameDesc::visibilityOf) read back as scene::RenderedVisibility.
scene::RenderedVisibility renderedVisibility(const rhi::Image& visibilityView);

// World size of one shadow-map texel of `light` at `position`, by the plans: the covering cascade's texel for a
// directional light, the tile's (or cube face's) texel at the position's distance from the light plane for
// spot and point lights. 0 where the light has no shadow map there.
float shadowTexelSize(const ShadowPlans& plans, const shadows::ShadowSettings& settings, const scene::Scene& scene,
                      const scene::LightRef& light, glm::vec3 position);

// The shadow ray of a G-buffer sample towards the light, as scene::traceLightVisibility and
// scene::tracePositionalLightVisibility cast it.
scene::ShadowRay truthShadowRay(const scene::Scene& scene, const scene::LightRef& light,
                                const scene::GBufferSample& sample);

// The ray-cast visibility of every pixel of `gbuffer` towards `light`.
scene::LightVisibilityMask traceTruth(const scene::Scene& scene, const scene::RayCaster& shadowRays,
                                      const scene::CpuGBuffer& gbuffer, const scene::LightRef& light,
                                      const scene::TraceProgress& progress = {});

// The light's name, or "<kind> <index>" when it has none.
std::string lightLabel(const scene::Scene& scene, const scene::LightRef& light);

} // namespace penumbra::render
