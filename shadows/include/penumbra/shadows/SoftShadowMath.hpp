#pragma once

#include "penumbra/shadows/ShadowSettings.hpp"

#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace penumbra::shadows {

// The C++ twins of shaders/soft_shadows.glsl: the Poisson and PCSS filters' math, tested on the CPU.

// PCG2D (Jarzynski and Olano 2020, "Hash Functions for GPU Rendering", section 3): two 32-bit words from two.
glm::uvec2 pcg2d(glm::uvec2 v);

// The Poisson disk's rotation at light-space texel `texel` (a texel of the light's own grid, so it stays with
// the receiver while the camera moves): an angle in [0, 2 pi); 0 everywhere when the rotation is off
// (SoftShadowSettings::diskRotation).
float diskRotationAngle(glm::ivec2 texel, Toggle rotation = Toggle::On);

// Receiver-plane depth bias (Isidoro 2006, "Receiver Plane Depth Bias", GDC): the change of the receiver plane's
// shadow-map depth per texel along x and y, from the screen-space derivatives dx, dy of its shadow-map position
// (texel x, texel y, depth). Zero where the derivatives are degenerate (the plane seen edge-on).
glm::vec2 receiverPlaneDepthGradient(glm::vec3 dx, glm::vec3 dy);

// Light-space distance past the near plane of an orthographic shadow-map depth; depthRow = (t22, t32) of the
// projection's texture-space depth row (depth = t22 * viewZ + t32).
float orthographicDistanceFromNear(float depth, glm::vec2 depthRow);

// View distance from a perspective light of a shadow-map depth (depth = (t22 * -z + t32) / z).
float perspectiveDistance(float depth, glm::vec2 depthRow);

// The clamp of a soft filter's radius, in texels.
struct PenumbraLimits {
    float minTexels = 1.0f;
    float maxTexels = 24.0f;
};

PenumbraLimits penumbraLimits(const SoftShadowSettings& soft);

// Directional light of angular diameter 2 atan(tanHalfAngle): its light reaches a receiver from a cone, so a
// blocker `receiverToBlocker` world units nearer the light blurs its edge over a radius of
// receiverToBlocker x tanHalfAngle world units, the same in every cascade. In texels of size `texelWorld`,
// x scale (the filter's radius: diskRadius).
float directionalPenumbraTexels(float receiverToBlocker, float tanHalfAngle, float texelWorld, float scale);

// The blocker search radius: the cone from the receiver to the light where it leaves the shadow map's near plane
// (w_search of Fernando 2005 with the nearest blocker at the near plane), in texels, clamped to at least one texel
// and at most the limit.
float directionalSearchTexels(float receiverFromNear, float tanHalfAngle, float texelWorld, float scale,
                              PenumbraLimits limits);

// Spot and point lights of radius R: lightTexels = R x f, f = tile size x P[0][0] / 2 the texels per unit of lateral
// size at unit distance. Penumbra radius R (zR - zB) / zB at the receiver, in its texels (zR / f world units):
// Fernando 2005's w_penumbra, x scale.
float perspectivePenumbraTexels(float receiverDistance, float blockerDistance, float lightTexels, float scale);

// Variance per axis, in texels^2, of one filter tap's own footprint: a bilinear comparison tap blurs by the tent of
// one texel, a nearest one (the cube maps' raw taps) by the box of one texel.
inline constexpr float kBilinearTapVariance = 1.0f / 6.0f;
inline constexpr float kNearestTapVariance = 1.0f / 12.0f;

// The radius of the disk of taps that blurs as the uniform disk of radius `penumbra` texels: a disk of radius r has
// the variance r^2 / 4 per axis and the variances of convolved kernels add, so r^2 = penumbra^2 - 4 tapVariance
// (0 where the taps alone blur as much). Without it every penumbra came out wider by the taps' own blur, near
// contact most. Clamped to the limits.
float diskRadius(float penumbra, float tapVariance, PenumbraLimits limits);

// w_search: the receiver-to-light cone's radius at the near plane, R (zR - n) / zR, in texels of that plane (n / f),
// x scale, clamped to at least one texel and at most the limit.
float perspectiveSearchTexels(float receiverDistance, float nearPlane, float lightTexels, float scale,
                              PenumbraLimits limits);

// The texel a nearest tap at texel-space position `position` reads, clamped into the tile.
glm::ivec2 clampTapTexel(glm::vec2 position, glm::ivec2 tileMin, glm::ivec2 tileMax);

// Tap positions (texel space) of a Poisson disk of `count` points, radius `radius` texels, rotated by `angle`,
// centred at `centre`.
std::vector<glm::vec2> poissonTaps(glm::vec2 centre, float radius, float angle, std::uint32_t count);

// A tile of depths and the convention's order: what the blocker search reads.
struct DepthTileView {
    std::function<float(glm::ivec2)> depthAt; // the stored depth of a texel inside the tile
    std::function<bool(float, float)> isNearer; // a nearer to the light than b
    glm::ivec2 tileMin{0};
    glm::ivec2 tileMax{0};
};

// What a blocker search found: the blockers' mean depth, their count and the nearest.
struct BlockerSearch {
    float averageDepth = 0.0f; // of the blockers found, shadow-map depth
    std::uint32_t blockers = 0;
    float nearestDepth = 0.0f; // the blocker nearest to the light; the receiver's depth without blockers
};

// The blocker search at texel-space position `centre`, receiver depth `depth` and receiver-plane gradient
// `gradient`: every tap's texel (clamped into the tile) whose depth is nearer than the receiver plane at that
// texel's centre is a blocker. Where no tap finds one, the receiver's own texel is read: a blocker there (a caster
// thinner than the taps' spacing) is the search's one blocker.
BlockerSearch searchBlockers(const DepthTileView& tile, glm::vec2 centre, float depth, glm::vec2 gradient, float radius,
                             float angle, std::uint32_t count);

} // namespace penumbra::shadows
