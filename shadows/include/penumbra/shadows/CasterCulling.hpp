#pragma once

#include "penumbra/shadows/Bounds.hpp"
#include "penumbra/shadows/CasterVolume.hpp"
#include "penumbra/shadows/DirectionalCascadeFit.hpp"
#include "penumbra/shadows/ShadowCamera.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace penumbra::shadows {

// The casters drawn into one cascade, and how many the culling bias left out.
struct CasterCullingResult {
    std::vector<std::uint32_t> casters; // indices into the caster list to draw into the cascade
    std::uint32_t overlapping = 0; // casters in the cascade's light box: the draws without culling bias
    std::uint32_t culledByBias = 0; // of those, skipped by the culling bias
};

// The document's shadowCascadeBlendCullingFactor, max(0, 0.8 - cascadeFade): lowered by the fade
// band and a margin so that casters in a blend region are never culled.
float cascadeBlendCullingFactor(float cascadeFade);

// Casters whose light-space box (in the cascade's basis, which must be the casters') meets the cascade's: the
// tile's square in x, y and depth up to the far plane (no near limit: casters in front of the near plane still
// cast, pancaked). The rules are cascadeVolume's (casterInVolume). With a previous cascade, a caster whose world box
// lies wholly inside that cascade's culling sphere scaled by cullingFactor is skipped (culling bias): the previous,
// sharper cascade already holds its shadow.
CasterCullingResult cullShadowCasters(const DirectionalShadowCascade& cascade, const LightSpaceCasters& casters,
                                      const std::optional<Sphere>& previousCullingSphere, float cullingFactor);

// Whether any caster may cast into a cascade around one of `cullingSpheres`: its light-space box meets the sphere's
// square (with a margin for the fit's texel snapping) in x and y and begins before the sphere's far end along the
// light. Every cascade's light box lies within that reach, so a light for which this is false draws nothing into its
// tiles and needs none.
bool castersInReach(const LightSpaceCasters& casters, std::span<const Sphere> cullingSpheres);

// Whether every corner of the box lies in the slice: inside the frustum's side planes, at view depths from
// nearDistance to nearDistance + (farDistance - nearDistance) * depthFactor.
bool insideFrustumSlice(const Bounds& box, const FrustumSlice& slice, float depthFactor);

// The close fit's rule, the same with the previous cascade's frustum slice for its sphere: a caster wholly inside
// that slice, its depth range scaled by cullingFactor from its near end, is skipped.
CasterCullingResult cullCloseFitShadowCasters(const DirectionalShadowCascade& cascade, const LightSpaceCasters& casters,
                                              const std::optional<FrustumSlice>& previousSlice, float cullingFactor);

} // namespace penumbra::shadows
