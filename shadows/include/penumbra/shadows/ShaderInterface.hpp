#pragma once

#include <cstdint>
#include <string>

namespace penumbra::shadows {

// Bindings of the shadow caster pass (shaders/shadow_caster.vert, shadow_caster_alpha.frag).
inline constexpr std::uint32_t kCasterDrawBinding = 0; // ShadowCasterUniforms
inline constexpr std::uint32_t kCasterBaseColorBinding = 1; // the alpha of Clip and Dither casters

// The GLSL include "shadow_interface.glsl" of every shader with shadow blocks: their array sizes and the enum values
// the shaders compare against, from the C++ declarations, so no number is written twice.
//   PENUMBRA_MAX_SHADOWED_DIRECTIONAL_LIGHTS, PENUMBRA_MAX_CASCADES, PENUMBRA_MAX_DIRECTIONAL_TILES,
//   PENUMBRA_MAX_SHADOW_CUBES                                        (DirectionalShadowUniforms, LocalShadowUniforms)
//   PENUMBRA_MAX_STATIC_DIRECTIONAL_MAPS, PENUMBRA_MAX_STATIC_LOCAL_TILES,
//   PENUMBRA_MAX_STATIC_MAP_DIRECTIONAL_LIGHTS (StaticShadowUniforms)
//   PENUMBRA_BLEND_HARD, _SOFT, _DITHER                              (CascadeBlend)
//   PENUMBRA_POINT_ATLAS, PENUMBRA_POINT_CUBE_MAP                    (PointShadowMode)
std::string shadowInterfaceGlsl();

// The GLSL include "caster_constants.glsl" of material.glsl: PENUMBRA_CASTER_OPAQUE, _CLIP, _DITHER
// (ShadowCasterMode) and the caster pass's bindings PENUMBRA_BINDING_CASTER_DRAW, PENUMBRA_BINDING_CASTER_BASE_COLOR.
std::string casterConstantsGlsl();

// The GLSL include "instance_constants.glsl" of instance.glsl: PENUMBRA_LOCATION_INSTANCE_ROWS, the first attribute
// location of InstanceTransform (addInstanceAttributes).
std::string instanceConstantsGlsl();

} // namespace penumbra::shadows
