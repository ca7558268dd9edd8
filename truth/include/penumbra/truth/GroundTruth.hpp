#pragma once

#include "penumbra/scene/Camera.hpp"
#include "penumbra/scene/Light.hpp"
#include "penumbra/truth/RayCaster.hpp"
#include "penumbra/scene/Scene.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace penumbra::truth {

// Ray-traced references for the shadow tests: what each pixel of a rendered picture shows
// (a CPU G-buffer) and whether that point sees a directional light.
//
// Pixels follow the RHI's conventions: row 0 is the top of the picture, pixel (x, y) covers
// [x, x + 1] x [y, y + 1] and its sample is the centre; NDC x = 2 (x + 0.5) / width - 1,
// NDC y = 1 - 2 (y + 0.5) / height (y up). The aspect ratio is width / height.

inline constexpr std::uint32_t kNoObject = std::numeric_limits<std::uint32_t>::max();

// A primary ray through the camera's near plane: it starts on the near plane and ends on
// the far plane, so that, as in rasterisation, nothing nearer than nearPlane is seen.
struct Ray {
    glm::vec3 origin;
    glm::vec3 direction; // unit
    float maxDistance;
};

// Ray through pixel coordinates (px, py) (continuous: the centre of pixel (x, y) is
// (x + 0.5, y + 0.5)).
Ray primaryRay(const scene::Camera& camera, std::uint32_t width, std::uint32_t height, float px, float py);

// What the CPU ray caster sees at one pixel: object, triangle, position, normals, uv, depth.
struct GBufferSample {
    std::uint32_t object = kNoObject; // kNoObject: background
    std::uint32_t triangle = 0; // within the object's mesh
    // The connected piece of the object's mesh the triangle belongs to (triangles joined by shared vertex positions):
    // a leaf card of a tree, not the tree.
    std::uint32_t surface = 0;
    glm::vec3 position{0.0f}; // world
    // Unit world normals turned towards the camera: back faces (of double-sided materials)
    // report the side that was seen. `normal` is the flat triangle normal; `shadingNormal`
    // interpolates the mesh's vertex normals as the lit pass does.
    glm::vec3 normal{0.0f};
    glm::vec3 shadingNormal{0.0f};
    glm::vec2 uv{0.0f};
    float viewDepth = 0.0f; // distance along the camera's forward axis
    bool frontFacing = true;

    // Whether the pixel's ray met an object.
    bool hit() const { return object != kNoObject; }
};

// The CPU ray caster's picture of a camera view, one sample per pixel.
struct CpuGBuffer {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<GBufferSample> samples; // row-major, row 0 at the top

    // The sample of pixel (x, y), row 0 at the top.
    const GBufferSample& at(std::uint32_t x, std::uint32_t y) const { return samples[std::size_t(y) * width + x]; }
};

// Called on the calling thread while a trace runs: rows finished so far, and of how many. The traces use every
// hardware thread; their results do not depend on how many there are.
using TraceProgress = std::function<void(std::uint32_t done, std::uint32_t rows)>;

// `cameraRays` must be built from `scene` with RayKind::Camera (throws std::invalid_argument
// otherwise).
CpuGBuffer traceGBuffer(const scene::Scene& scene, const RayCaster& cameraRays, const scene::Camera& camera,
                        std::uint32_t width, std::uint32_t height, const TraceProgress& progress = {});

enum class LightVisibility : std::uint8_t {
    Background, // no surface
    Lit, // faces the light and nothing blocks it
    Shadowed, // faces the light, something blocks it
    // Faces the light, only dithered casters block it: their shadow is a stipple whose share of lit texels is
    // 1 - ditherCoverage, so a pixel's answer depends on the dither, not on the shadow's place; compare on average.
    Dithered,
    FacingAway, // the light arrives from behind the surface (dot(normal, -direction) <= 0): unlit, shadow or not
    NotReceiving, // the material has receiveShadows = false: drawn lit whatever blocks it
};

// Per pixel of a G-buffer, whether a light reaches it, by a shadow ray each.
struct LightVisibilityMask {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<LightVisibility> pixels; // row-major, row 0 at the top
    // Where Shadowed: the object the shadow ray meets first (the caster nearest the receiver); kNoObject elsewhere.
    std::vector<std::uint32_t> blockers;
    // Where Dithered: Occlusion::ditherCoverage of its shadow ray; 0 elsewhere.
    std::vector<float> ditherCoverage;

    // The visibility of pixel (x, y), row 0 at the top.
    LightVisibility at(std::uint32_t x, std::uint32_t y) const { return pixels[std::size_t(y) * width + x]; }
};

// Shadow rays start this far off the surface along its normal (world units): far above
// float rounding at the test scene's 60-unit scale, far below any feature a test measures.
inline constexpr float kShadowRayOffset = 1e-3f;

// A shadow ray towards a light, from a given origin.
struct ShadowRay {
    glm::vec3 origin;
    glm::vec3 direction; // unit, towards the light
    float maxDistance; // to the light; infinite for a directional light
};
using ShadowRayFrom = std::function<ShadowRay(glm::vec3 origin)>;
ShadowRayFrom raysTowards(const scene::DirectionalLight& light);
ShadowRayFrom raysTowards(glm::vec3 lightPosition);

// A shadow ray's class: Shadowed behind a solid blocker, else Dithered behind dithered ones, else Lit.
LightVisibility visibilityOf(const Occlusion& occlusion);

// Where a sample's shadow ray leaves: position + normal * normalOffset.
glm::vec3 shadowRayOrigin(const GBufferSample& sample, float normalOffset = kShadowRayOffset);

// For every G-buffer sample: an occlusion ray from shadowRayOrigin(sample, normalOffset) towards the light.
// `shadowRays` must be built with RayKind::Shadow (throws std::invalid_argument otherwise).
LightVisibilityMask traceVisibility(const scene::Scene& scene, const RayCaster& shadowRays, const CpuGBuffer& gbuffer,
                                    const ShadowRayFrom& rayFrom, float normalOffset = kShadowRayOffset,
                                    const TraceProgress& progress = {});

// traceVisibility towards a directional light (rays along -light.direction) or a spot or point light at
// `lightPosition` (rays end at the light).
LightVisibilityMask traceLightVisibility(const scene::Scene& scene, const RayCaster& shadowRays,
                                         const CpuGBuffer& gbuffer, const scene::DirectionalLight& light,
                                         float normalOffset = kShadowRayOffset);
LightVisibilityMask tracePositionalLightVisibility(const scene::Scene& scene, const RayCaster& shadowRays,
                                                   const CpuGBuffer& gbuffer, glm::vec3 lightPosition,
                                                   float normalOffset = kShadowRayOffset);

} // namespace penumbra::truth
