#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/CubeMap.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"
#include "penumbra/shadows/SoftShadowUniforms.hpp"

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace penumbra::shadows {

// The six faces of a point light's shadow, in the order tiles and cube layers use.
using rhi::CubeFace;
inline constexpr std::uint32_t cubeFaceCount = 6;

// Unit axis a face looks along.
glm::vec3 cubeFaceAxis(CubeFace face);

// The face whose axis has the largest component of `direction` (light to point); ties go to x, then y,
// then z. shaders/local_shadows.glsl implements the same rule.
CubeFace cubeFace(glm::vec3 direction);

// A right-handed camera at `position` looking along the face's axis: an ordinary, unmirrored view,
// so front faces stay front faces and no row of it is negated (Unity renders cube faces upside down
// and undoes it that way, as Catlike Coding's "Point and Spot Shadows" tutorial shows).
glm::mat4 pointFaceView(CubeFace face, glm::vec3 position);

// A right-handed camera at `position` looking along `direction` (unit), with any stable up vector.
glm::mat4 spotView(glm::vec3 position, glm::vec3 direction);

// Near plane of a spot or point shadow projection: the light's own (`lightNearPlane`, world units) or, where it
// sets none (0), `settings.nearPlane` times its range.
float localShadowNearPlane(float range, float lightNearPlane, const LocalShadowSettings& settings);

// World-space texel size at distance 1 from the light plane: the tile spans 2 / projection[0][0]
// there (twice the tangent of half the field of view).
float texelSizeAtUnitDistance(const glm::mat4& projection, std::uint32_t tileSize);

// What the Poisson and PCSS filters need of a perspective tile (LocalShadowUniforms::tileSoft and
// StaticShadowUniforms::localSoft).
PerspectiveTileSoft perspectiveTileSoft(const glm::mat4& projection, std::uint32_t tileSize, float sourceRadius,
                                        float nearPlane, const rhi::Conventions& conventions);

// Normal bias per unit distance from the light plane: texel size x filter size x sqrt 2 (a texel's
// diagonal is the worst case), times the light's normal bias.
float localNormalBiasScale(const glm::mat4& projection, std::uint32_t tileSize, ShadowFilter filter, float normalBias);

// Field of view of a point light's face tiles, widened so that normal bias and filter taps near a
// face edge stay inside the tile: tan(fov / 2) = 1 + bias + filter size at distance 1.
float pointFaceFieldOfView(std::uint32_t tileSize, ShadowFilter filter, float normalBias);

// Field of view of a spot light's tile: its cone (twice the outer angle) or, with the FOV bias (the settings'
// local.spotFovBias), widened as the point faces are: tan(fov / 2) = tan(outer angle) + bias + filter size at
// distance 1, the texel size that of the cone's own tile (the document's approximation: the widening's own texel
// growth is left out).
float spotFieldOfView(float outerAngle, std::uint32_t tileSize, ShadowFilter filter, float normalBias, Toggle fovBias);

// The document's FOV bias in degrees: atan(1 + bias + filter size) x 2 - 90.
float pointFaceFovBiasDegrees(std::uint32_t tileSize, ShadowFilter filter, float normalBias);

} // namespace penumbra::shadows
