#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/shadows/Bounds.hpp"
#include "penumbra/shadows/DirectionalCascadeFit.hpp"
#include "penumbra/shadows/LightBasis.hpp"
#include "penumbra/shadows/SoftShadowUniforms.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <span>

namespace penumbra::shadows {

// What the Poisson and PCSS filters (shaders/soft_shadows.glsl) need of a directional tile (DirectionalTileSoft), the
// realtime cascades' and the static maps' alike.

// What a tile texel adds to become the light's own texel grid (whole texels: the fit snaps the tile's centre), per
// axis in the direction the atlas runs along the light's right and up axes; `worldToAtlas` is the tile's.
glm::vec2 lightTexelAnchor(const DirectionalShadowCascade& fit, const glm::mat4& worldToAtlas);

// The light-space depth nearest the light of any caster: no blocker lies nearer. Unlike the near plane, which follows
// the cascade's sphere, it does not move with the camera, so neither does the blocker search sized from it.
float casterTopDepth(const LightSpaceCasters& casters, float fallback);

// The projection's texture-space depth row (t22, t32'): depth = t22 * viewZ + t32, with t32' = t32 + t22 (near -
// casterTop), so that orthographicDistanceFromNear(depth, row) is the distance past the casters' top (the blocker
// search's receiver depth), and differences of two depths stay world distances.
glm::vec2 directionalDepthRow(const DirectionalShadowCascade& fit, float casterTop,
                              const rhi::Conventions& conventions);

// A directional tile's soft data: its light texel anchor and the depth row from the top of `casters` (the fit's near
// depth without any); `worldToAtlas` is the tile's.
DirectionalTileSoft directionalTileSoft(const DirectionalShadowCascade& fit, const glm::mat4& worldToAtlas,
                                        const LightSpaceCasters& casters, const rhi::Conventions& conventions);

} // namespace penumbra::shadows
