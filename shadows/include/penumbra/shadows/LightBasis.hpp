#pragma once

#include "penumbra/shadows/Bounds.hpp"

#include <array>
#include <span>
#include <limits>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace penumbra::shadows {

// Orthonormal light-space axes of a directional light; a function of the direction alone, so
// that light-space texel grids stay put while the camera moves. right x up = -direction, as the
// light view (right-handed, looking down -z) needs.
struct LightBasis {
    glm::vec3 right{1.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; // from the light into the scene

    // (x, y, depth along the light) of a world point.
    glm::vec3 toLight(glm::vec3 p) const { return {glm::dot(p, right), glm::dot(p, up), glm::dot(p, direction)}; }
};

// `direction` must be non-zero; it is normalised.
LightBasis lightBasis(glm::vec3 direction);

// Light-space (x, y, depth) box around a world box's 8 corners.
Bounds lightSpaceBounds(const LightBasis& basis, const Bounds& world);
// Around 8 world points (a frustum slice's corners: the close fit's bounds).
Bounds lightSpaceBounds(const LightBasis& basis, const std::array<glm::vec3, 8>& corners);

// Casters' world boxes and their light-space boxes (lightSpaceBounds) in one light's basis: transformed once per
// light, then read by every cascade's fit, culling and soft-shadow data, which matters at 10^5 casters.
struct LightSpaceCasters {
    LightBasis basis;
    std::span<const Bounds> world; // caster i's world box
    std::vector<Bounds> light; // caster i's light-space box
    // Chunk k: the light-space box around light[k * kLightSpaceChunk, (k + 1) * kLightSpaceChunk). The fits' near
    // planes (nearestDepthOver) read the boxes of the chunks a square cuts only, so that a cascade over a part of 10^6
    // casters does not read every box; casters of one mesh's instances lie near their neighbours in the list.
    std::vector<Bounds> chunks;
    // The least light-space depth of any caster (the nearest to the light), the largest float without casters:
    // every cascade's soft shadow data asks for it (casterTopDepth), so it is found once per light.
    float top = std::numeric_limits<float>::max();
};

// Casters per LightSpaceCasters::chunks box.
inline constexpr std::size_t kLightSpaceChunk = 64;

// `world` must outlive the result, which refers to it.
LightSpaceCasters lightSpaceCasters(const LightBasis& basis, std::span<const Bounds> world);

// Makes the chunks holding casters [first, end) anew from their light boxes (after those changed).
void refitChunks(LightSpaceCasters& casters, std::size_t first, std::size_t end);
// Makes `top` anew from the chunks (after refitChunks).
void refitTop(LightSpaceCasters& casters);

// The least light-space depth (min.z) of the caster boxes whose light-space footprint overlaps the square of `halfSize`
// around `centre` (edges included), or `start` where it is less: the same number as a test of every box, since a
// chunk wholly inside the square gives its least depth, one outside or no nearer than the depth so far is skipped.
float nearestDepthOver(const LightSpaceCasters& casters, glm::vec2 centre, float halfSize, float start);

} // namespace penumbra::shadows
