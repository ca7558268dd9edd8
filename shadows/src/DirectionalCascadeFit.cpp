#include "penumbra/shadows/DirectionalCascadeFit.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

namespace penumbra::shadows {
namespace {

// Rows right, up, -direction with the eye at (snapped x, snapped y, near depth) in light space;
// built from the light-space numbers directly so the snapped translation is exact.
glm::mat4 lightView(const LightBasis& b, glm::vec2 snapped, float nearDepth)
{
    glm::mat4 view(1.0f);
    for (int axis = 0; axis < 3; ++axis) {
        view[axis][0] = b.right[axis];
        view[axis][1] = b.up[axis];
        view[axis][2] = -b.direction[axis];
    }
    view[3][0] = -snapped.x;
    view[3][1] = -snapped.y;
    view[3][2] = nearDepth;
    return view;
}

// Depth planes and matrices of a fit whose square (halfSize, snappedCentre) is set: the near plane at minDepth pulled
// back over every caster box whose light-space footprint overlaps the square, then by nearPlaneOffset; the far plane
// at maxDepth; both then moved outwards onto depthPlaneGrid.
void placeDepthPlanes(DirectionalShadowCascade& c, float minDepth, float maxDepth, float nearPlaneOffset,
                      const LightSpaceCasters& casters, const rhi::Conventions& conventions)
{
    c.nearDepth = nearestDepthOver(casters, c.snappedCentre, c.halfSize, minDepth);
    const float grid = depthPlaneGrid(c.texelSize);
    c.nearDepth = std::floor((c.nearDepth - nearPlaneOffset) / grid) * grid;
    c.farDepth = std::ceil(maxDepth / grid) * grid;

    c.view = lightView(c.basis, c.snappedCentre, c.nearDepth);
    c.projection =
        conventions.orthographic(-c.halfSize, c.halfSize, -c.halfSize, c.halfSize, 0.0f, c.farDepth - c.nearDepth);
    c.viewProjection = c.projection * c.view;
}

glm::vec2 snapToTexels(glm::vec2 centre, float texelSize) { return glm::round(centre / texelSize) * texelSize; }

} // namespace

float depthPlaneGrid(float texelSize) { return std::exp2(std::ceil(std::log2(16.0f * texelSize))); }

DirectionalShadowCascade fitDirectionalCascade(const Sphere& sphere, const LightSpaceCasters& casters,
                                               std::uint32_t tileSize, float nearPlaneOffset,
                                               const rhi::Conventions& conventions)
{
    DirectionalShadowCascade c;
    c.basis = casters.basis;
    c.cullingSphere = sphere;
    const float tile = static_cast<float>(tileSize);
    // h = r + (sqrt 2 / 2) texel with texel = 2h / tile: the snap moves the centre at most half a texel diagonal.
    c.halfSize = sphere.radius / (1.0f - std::sqrt(2.0f) / tile);
    c.texelSize = 2.0f * c.halfSize / tile;
    const glm::vec3 centre = c.basis.toLight(sphere.centre);
    c.fittedCentre = glm::vec2(centre);
    c.snappedCentre = snapToTexels(c.fittedCentre, c.texelSize);
    placeDepthPlanes(c, centre.z - sphere.radius, centre.z + sphere.radius, nearPlaneOffset, casters, conventions);
    return c;
}

float closeFitHalfSize(const Bounds& sliceBounds, std::uint32_t tileSize, float marginTexels)
{
    // h = e + (m + 1/2) texel with texel = 2h / tile.
    const glm::vec3 extent = sliceBounds.max - sliceBounds.min;
    const float half = 0.5f * std::max(extent.x, extent.y);
    const float exact = half / (1.0f - (2.0f * marginTexels + 1.0f) / static_cast<float>(tileSize));
    // Rounded up to 12 significant bits (at most 0.05 % larger): float rounding of a translated slice's corners
    // changes its bounds' size by an ulp or so, which would move every snapped texel as the camera translates.
    int exponent = 0;
    std::frexp(exact, &exponent);
    const float quantum = std::ldexp(1.0f, exponent - 12);
    return std::ceil(exact / quantum) * quantum;
}

DirectionalShadowCascade fitCloseCascade(const Bounds& sliceBounds, float halfSize, const Sphere& sphere,
                                         const LightSpaceCasters& casters, std::uint32_t tileSize,
                                         float nearPlaneOffset, const rhi::Conventions& conventions)
{
    DirectionalShadowCascade c;
    c.basis = casters.basis;
    c.cullingSphere = sphere;
    c.halfSize = halfSize;
    c.texelSize = 2.0f * c.halfSize / static_cast<float>(tileSize);
    c.fittedCentre = 0.5f * glm::vec2(sliceBounds.min + sliceBounds.max);
    c.snappedCentre = snapToTexels(c.fittedCentre, c.texelSize);
    placeDepthPlanes(c, sliceBounds.min.z, sliceBounds.max.z, nearPlaneOffset, casters, conventions);
    return c;
}

std::vector<DirectionalShadowCascade> computeDirectionalShadowMatricesAndCullingPrimitives(
    const ShadowCamera& camera, const CascadeSplits& splits, std::uint32_t firstCascade, std::uint32_t count,
    glm::vec3 lightDirection, std::uint32_t tileSize, float nearPlaneOffset, std::span<const Bounds> casterBounds,
    const rhi::Conventions& conventions)
{
    const LightSpaceCasters casters = lightSpaceCasters(lightBasis(lightDirection), casterBounds);
    std::vector<DirectionalShadowCascade> cascades;
    for (std::uint32_t i = firstCascade; i < firstCascade + count; ++i) {
        const Sphere sphere = frustumSliceSphere(camera, splits.nearOf(i), splits.farOf(i));
        cascades.push_back(fitDirectionalCascade(sphere, casters, tileSize, nearPlaneOffset, conventions));
    }
    return cascades;
}

} // namespace penumbra::shadows
