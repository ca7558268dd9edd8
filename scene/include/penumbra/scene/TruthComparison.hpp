#pragma once

#include "penumbra/scene/GroundTruth.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <vector>

namespace penumbra::scene {

// A renderer's shadow-map visibility of one light, per pixel in the ground truth's layout (row 0 at the top):
// `lit` in [0, 1] (1 = lit) where `decided` is set; elsewhere the shadow map has no say (the light does not
// reach the pixel, no cascade or tile covers it, the material receives no shadows).
struct RenderedVisibility {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<float> lit;
    std::vector<std::uint8_t> decided;
};

// Pixels this close (in pixels, on either axis) to a change of ground-truth class or of object are shadow or
// silhouette edges, where one pixel's answer depends on the sub-pixel position of an edge.
inline constexpr int kTruthEdgeMargin = 2;
// A pixel is rendered in shadow when less than half of the light gets through.
inline constexpr float kShadowedBelow = 0.5f;

// What the comparison concluded at a pixel.
enum class TruthVerdict : std::uint8_t {
    NotCompared, // background, facing away from the light, not receiving
    Undecided, // truly lit or shadowed, but the shadow map has no say there
    NearEdge, // within kTruthEdgeMargin of a change of class or object, or near a shadow edge in the light's view
    LitRight,
    ShadowedRight,
    Acne, // truly lit, rendered in shadow
    Leak, // truly shadowed, rendered lit
};

// The pixels of one ground-truth class: compared ones, and those left out (and why).
struct TruthClassFigures {
    std::size_t compared = 0;
    std::size_t right = 0;
    std::size_t nearEdges = 0;
    std::size_t undecided = 0;

    double share() const { return compared == 0 ? 0.0 : double(right) / double(compared); }
};

// Figures per class, so that a picture of mostly lit pixels cannot hide a missing shadow.
struct TruthComparison {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<TruthVerdict> verdicts; // row-major, row 0 at the top
    TruthClassFigures lit;
    TruthClassFigures shadowed;
    // The shadowed class by the caster nearest each receiver (LightVisibilityMask::blockers): a missing or
    // misplaced caster shows in its own figures however small its shadow is beside the others.
    std::map<std::uint32_t, TruthClassFigures> shadowedBy;

    std::size_t compared() const { return lit.compared + shadowed.compared; }
    std::size_t acne() const { return lit.compared - lit.right; }
    std::size_t leaks() const { return shadowed.compared - shadowed.right; }
    // Of all compared pixels, the share rendered right.
    double agreement() const { return compared() == 0 ? 0.0 : double(lit.right + shadowed.right) / double(compared()); }
    TruthVerdict at(std::uint32_t x, std::uint32_t y) const { return verdicts[std::size_t(y) * width + x]; }
};

// Shadow edges as a shadow map sees them. A map of texel size s whose filter reaches f texels around the lookup
// and whose normal offset moves the lookup by up to b texels may place an edge anywhere within (f + b + 1/2) s of
// the exact one, however many pixels that covers on screen (many, where light grazes a receiver). A sample is
// near a shadow edge when its ray-cast visibility differs at one of 8 points around it on its tangent plane
// whose projections across the light's rays lie radius(sample) (world units) from its own, in the directions
// of a square's sides and diagonals (lifted off the plane by a tenth of their distance along it, over creases of
// up to 5 degrees). A sample whose tangent plane is within 3 degrees of the light's rays is
// near an edge. Returns 1 for those samples; 0 elsewhere and for samples neither truly lit nor shadowed.
std::vector<std::uint8_t> traceShadowEdges(const RayCaster& shadowRays, const CpuGBuffer& gbuffer,
                                           const LightVisibilityMask& truth, const ShadowRayFrom& rayFrom,
                                           const std::function<float(const GBufferSample&)>& radius,
                                           const TraceProgress& progress = {});

// `shadowEdges` (traceShadowEdges, or empty for none) adds its samples to the edges left out. Throws
// std::invalid_argument when the pictures differ in size.
TruthComparison compareWithTruth(const CpuGBuffer& gbuffer, const LightVisibilityMask& truth,
                                 const RenderedVisibility& rendered, const std::vector<std::uint8_t>& shadowEdges = {},
                                 int edgeMargin = kTruthEdgeMargin);

// Peter-panning: the largest distance along the light from a leak pixel to the surface that truly shadows it,
// in shadow-map texels at that pixel (`texelSize(position)`, world units). Leaks farther than
// `contactTexels` from their blocker are misplaced shadow edges (counted in TruthComparison::leaks), not gaps at
// a contact. 0 without leaks near a contact.
inline constexpr float kContactTexels = 8.0f;
float contactGapTexels(const TruthComparison& comparison, const CpuGBuffer& gbuffer, const RayCaster& shadowRays,
                       const ShadowRayFrom& rayFrom, const std::function<float(glm::vec3)>& texelSize,
                       float contactTexels = kContactTexels);

} // namespace penumbra::scene
