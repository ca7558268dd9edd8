#pragma once

#include "penumbra/shadows/DirectionalShadowUniforms.hpp"

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>

namespace penumbra::shadows {

// The C++ twin of selectCascade in directional_shadows.glsl, before the blend mode is applied: which cascade a
// receiver at world `position` and camera view depth `viewDepth` takes.
// - Stable fit: the first cascade whose selection sphere (the culling sphere shrunk by the filter) holds the point;
//   the fade runs over the sphere's outer cascadeFade fraction, on squared distance.
// - Close fit: the first cascade whose far split the view depth has not reached; the fade runs linearly over the
//   last cascadeFade fraction of that depth (Unity's "Close Fit" bands, Catlike Coding, "Rendering 7: Shadows",
//   section 1.7).
// - Depth fit: the first cascade whose tile of shadow slot `slot`'s light holds the point, more than twice the
//   filter's reach inside its edges (map-based selection: Microsoft, "Cascaded Shadow Maps"): each light selects in
//   its own tiles, which the planner fits around that light's footprint. The fade runs over the cascadeFade fraction
//   of the tile's half size inside that; the margin is in world units. The other projections ignore `slot`.
struct CascadeSelection {
    std::uint32_t index = 0; // the cascade count when no cascade holds the point
    float fade = 1.0f; // 1 inside, falling to 0 at the region's outer edge: the blend weight of `index`
    float margin = 0.0f; // world distance from the point to that edge (radius or depth)
};

CascadeSelection selectCascade(const DirectionalShadowUniforms& uniforms, glm::vec3 position, float viewDepth,
                               std::uint32_t slot = 0);

// The part of the lit shader's include "shadow_constants.glsl" that names the projections:
//   PENUMBRA_PROJECTION_<NAME>      CascadeProjection values (STABLE, CLOSE)
std::string cascadeProjectionConstantsGlsl();

} // namespace penumbra::shadows
