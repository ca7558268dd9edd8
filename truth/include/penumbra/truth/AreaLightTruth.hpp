#pragma once

#include "penumbra/truth/GroundTruth.hpp"
#include "penumbra/scene/Light.hpp"
#include "penumbra/truth/TruthComparison.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace penumbra::truth {

// Ray-traced soft shadows: the share of an area light a surface point sees.

// A light with a size: a disk at infinity of angular radius atan(tanHalfAngle) around `direction` (a directional
// light), or a disk of `radius` around `position` facing each receiver (a spot or point light's sphere, seen from
// the receiver as its silhouette disk).
struct AreaLightSource {
    bool atInfinity = true;
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // into the scene (directional)
    float tanHalfAngle = 0.0f;
    glm::vec3 position{0.0f};
    float radius = 0.0f;
};

AreaLightSource areaLightOf(const scene::DirectionalLight& light); // angularDiameter, degrees
AreaLightSource areaLightOf(const scene::SpotLight& light);
AreaLightSource areaLightOf(const scene::PointLight& light);

// Rays per pixel: a raysPerSide x raysPerSide stratified grid on the light's disk (Shirley and Chiu 1997, "A
// Low Distortion Map Between Disk and Square"), each stratum jittered by a hash of the pixel and the stratum, so the
// result is the same every run and on every thread count.
inline constexpr std::uint32_t kAreaLightRaysPerSide = 16; // 256 rays

// Per pixel: the share of the light's rays that reach it unblocked (1 = fully lit), where `valid` is set: a
// receiving surface facing the light's centre. Elsewhere 1 and 0.
struct SoftVisibilityMap {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<float> lit;
    std::vector<std::uint8_t> valid;

    // Visibility of pixel (x, y), row 0 at the top.
    float at(std::uint32_t x, std::uint32_t y) const { return lit[std::size_t(y) * width + x]; }
};

// `shadowRays` must be built with RayKind::Shadow (throws std::invalid_argument otherwise).
SoftVisibilityMap traceAreaLightVisibility(const scene::Scene& scene, const RayCaster& shadowRays,
                                           const CpuGBuffer& gbuffer, const AreaLightSource& light,
                                           std::uint32_t raysPerSide = kAreaLightRaysPerSide,
                                           const TraceProgress& progress = {});

// A pixel is in the true penumbra when its visibility lies strictly inside (kPenumbraEpsilon, 1 - kPenumbraEpsilon);
// soft-shadow errors are taken over those pixels and those within kPenumbraMargin pixels of one.
inline constexpr float kPenumbraEpsilon = 0.02f;
inline constexpr int kPenumbraMargin = 2;

// How far a rendered soft shadow is from the ray-traced area light's, over the true penumbra.
struct SoftTruthFigures {
    std::size_t penumbraPixels = 0; // truly in the penumbra (and decided by the renderer)
    std::size_t compared = 0; // in or near it, valid in the truth and decided by the renderer
    double meanAbsError = 0.0; // mean |rendered - truth| over `compared`
    double maxAbsError = 0.0;
};

// Throws std::invalid_argument when the pictures differ in size.
SoftTruthFigures compareSoftVisibility(const SoftVisibilityMap& truth, const RenderedVisibility& rendered,
                                       int margin = kPenumbraMargin);

} // namespace penumbra::truth
