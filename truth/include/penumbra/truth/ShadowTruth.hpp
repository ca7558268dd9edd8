#pragma once

#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/Light.hpp"
#include "penumbra/truth/TruthComparison.hpp"

#include <glm/vec3.hpp>

namespace penumbra::truth {

// What the renderer's shadow maps say against a CPU ray cast (truth::GroundTruth), per light.

// The visibility view (FrameDesc::visibilityOf) read back as RenderedVisibility.
RenderedVisibility renderedVisibility(const rhi::Image& visibilityView);

// World size of one shadow-map texel of `light` at `position`, by the plans: the covering cascade's texel for a
// directional light, the tile's (or cube face's) texel at the position's distance from the light plane for
// spot and point lights. 0 where the light has no shadow map there.
float shadowTexelSize(const render::ShadowPlans& plans, const shadows::ShadowSettings& settings,
                      const scene::Scene& scene, const scene::LightRef& light, glm::vec3 position);

// Effective shadow resolution on screen: texels per metre of directional light `lightIndex`'s map on receivers at
// view depth `viewDepth`, the mean of 1 / texel size of the cascade the lit shader selects over a 16 x 9 grid across
// the picture (width / height `aspect`) at that depth; 0 where no cascade covers any of it.
float directionalTexelsPerMetre(const shadows::DirectionalShadowPlan& plan, std::uint32_t lightIndex,
                                const scene::Camera& camera, float aspect, float viewDepth);

// Texels per metre of a directional light's map over the surfaces a camera sees: 1 / texel size of the cascade the
// lit shader selects at each G-buffer sample that has one, their median and 10th percentile (the coarse end), and
// how many samples had a cascade. Zeros where none had.
struct OnScreenTexelDensity {
    float median = 0.0f;
    float tenthPercentile = 0.0f;
    std::size_t samples = 0;
};
OnScreenTexelDensity directionalTexelsOnScreen(const shadows::DirectionalShadowPlan& plan, std::uint32_t lightIndex,
                                               const scene::Camera& camera, const CpuGBuffer& gbuffer);

// Shadow rays towards `light`, as the ray cast casts them.
ShadowRayFrom truthRays(const scene::Scene& scene, const scene::LightRef& light);

// How far from an exact shadow edge a correct shadow map of the plans may place it, in its texels: the filter's
// reach k (1, 2, 3, 4 for the 2x2, 3x3, 5x5 and 7x7 filters), the default normal offset's lateral move of up to
// k sqrt 2, and half a texel of rasterisation. Taken at the default normal bias, so that a larger one shows.
float shadowEdgeMarginTexels(shadows::ShadowFilter filter);

// How far across the light's rays a correct lookup of `filter` reads around its point, in texels: the filter's reach
// k (as in shadowEdgeMarginTexels) and half a texel of rasterisation.
float lookupFootprintTexels(shadows::ShadowFilter filter);

// The ray cast of `light` for every sample of `gbuffer`, and its shadow edges at the resolution `plans` give the
// light (traceShadowEdges with shadowEdgeMarginTexels texels), and what compareLightTruth confirms
// disagreements with: the rays and each pixel's lookup footprint (lookupFootprintTexels, around the receiver moved
// by the default normal offset; radius 0 where the light has no shadow map).
struct LightTruthTrace {
    LightVisibilityMask visibility;
    std::vector<std::uint8_t> shadowEdges;
    std::vector<LookupFootprint> footprints;
    ShadowRayFrom rays;
};
LightTruthTrace traceLightTruth(const scene::Scene& scene, const RayCaster& shadowRays, const CpuGBuffer& gbuffer,
                                const render::ShadowPlans& plans, const shadows::ShadowSettings& settings,
                                const scene::LightRef& light, const TraceProgress& progress = {});

// A rendered visibility against the trace: compareWithTruth, its disagreements confirmed
// (confirmDisagreements) with the rays of `shadowRays`, the caster the trace was cast with.
TruthComparison compareLightTruth(const LightTruthTrace& trace, const RayCaster& shadowRays, const CpuGBuffer& gbuffer,
                                  const RenderedVisibility& rendered);

// The light's name, or "<kind> <index>" when it has none.
std::string lightLabel(const scene::Scene& scene, const scene::LightRef& light);

} // namespace penumbra::truth
