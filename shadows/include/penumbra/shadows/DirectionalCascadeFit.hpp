#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/shadows/Bounds.hpp"
#include "penumbra/shadows/CascadeSplits.hpp"
#include "penumbra/shadows/FrustumSliceSphere.hpp"
#include "penumbra/shadows/LightBasis.hpp"
#include "penumbra/shadows/ShadowCamera.hpp"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <array>
#include <span>
#include <vector>

namespace penumbra::shadows {

// One cascade of one directional light: what ComputeDirectionalShadowMatricesAndCullingPrimitives returns.
struct DirectionalShadowCascade {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProjection{1.0f}; // projection * view
    // The frustum slice's bounding sphere: the stable fit's cascade selection and culling bias use it.
    // Independent of the light, so every light shares it.
    Sphere cullingSphere;
    // Half the side of the square the tile covers in light space: the sphere's radius (stable fit) or half the
    // larger side of the slice's light-space bounds plus the filter margin (close fit), plus the largest snapping
    // displacement, so the snapped square still holds the whole sphere or slice.
    float halfSize = 0.0f;
    float texelSize = 0.0f; // world size of one tile texel, 2 halfSize / tileSize
    glm::vec2 fittedCentre{0.0f}; // light-space x, y of what the tile is fitted around, before the snap
    glm::vec2 snappedCentre{0.0f}; // light-space x, y of the tile's centre: whole texels
    float nearDepth = 0.0f; // light-space depth (along the direction) of the near plane
    float farDepth = 0.0f; // of the far plane: the sphere's far side
    LightBasis basis;
};

// The step of the grid the cascades' near and far planes lie on: the power of two of at least 16 texels, so that a
// camera move inside one step leaves every depth a tile holds the same to the bit, as the snap leaves its texels.
float depthPlaneGrid(float texelSize);

// Fits one cascade's light projection around `sphere` (stable fit):
// - light view along basis.direction; orthographic square of half size r / (1 - sqrt 2 / tileSize);
// - the square's centre snapped to whole texels in light space, so camera translation moves
//   shadow texels by whole texels only;
// - near plane pulled back over every caster box whose light-space footprint overlaps the square,
//   then by nearPlaneOffset; far plane at the sphere's far side; both moved outwards onto depthPlaneGrid;
// - projection from conventions.orthographic, so every depth range and reversed-Z works.
// The light's basis is the casters' (casters.basis).
DirectionalShadowCascade fitDirectionalCascade(const Sphere& sphere, const LightSpaceCasters& casters,
                                               std::uint32_t tileSize, float nearPlaneOffset,
                                               const rhi::Conventions& conventions);

// The half size of a close-fit tile around `sliceBounds` (lightSpaceBounds of a frustum slice's corners: x, y the
// tile's footprint, z its depth range): half its larger side, plus marginTexels texels (a
// receiver's normal offset and filter taps stay in the tile), plus half a texel (the snap moves the centre at most
// half a texel along each axis), rounded up to 12 significant bits so that camera translation leaves it alone. A
// square, not the bounds' rectangle: square texels keep one texel size per cascade for the normal bias, the filters
// and the soft shadows' penumbrae.
float closeFitHalfSize(const Bounds& sliceBounds, std::uint32_t tileSize, float marginTexels);

// Fits one cascade's light projection around a frustum slice (close fit): the square of half size halfSize (at
// least closeFitHalfSize) centred on the slice's light-space bounds, snapped to whole texels as the stable fit is
// (the bounds of a translated slice are the translated bounds, so camera translation still moves shadow texels by
// whole texels; turning the camera resizes the tile, and texels swim); near and far planes as the stable fit's,
// around the slice's depth range. `sphere` is kept as the cascade's cullingSphere.
DirectionalShadowCascade fitCloseCascade(const Bounds& sliceBounds, float halfSize, const Sphere& sphere,
                                         const LightSpaceCasters& casters, std::uint32_t tileSize,
                                         float nearPlaneOffset, const rhi::Conventions& conventions);

// The engine function written out: cascades [firstCascade, firstCascade + count) of one light.
std::vector<DirectionalShadowCascade> computeDirectionalShadowMatricesAndCullingPrimitives(
    const ShadowCamera& camera, const CascadeSplits& splits, std::uint32_t firstCascade, std::uint32_t count,
    glm::vec3 lightDirection, std::uint32_t tileSize, float nearPlaneOffset, std::span<const Bounds> casterBounds,
    const rhi::Conventions& conventions);

} // namespace penumbra::shadows
