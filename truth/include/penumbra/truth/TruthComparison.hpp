#pragma once

#include "penumbra/truth/GroundTruth.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <vector>

namespace penumbra::truth {

// A renderer's shadow-map visibility of one light, per pixel in the ground truth's layout (row 0 at the top):
// `lit` in [0, 1] (1 = lit) where `decided` is set; elsewhere the shadow map has no say (the light does not
// reach the pixel, no cascade or tile covers it, the material receives no shadows).
struct RenderedVisibility {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<float> lit;
    std::vector<std::uint8_t> decided;
};

// Pixels this close (in pixels, on either axis) to a change of ground-truth class or of surface are shadow or
// silhouette edges, where one pixel's answer depends on the sub-pixel position of an edge. A neighbour is on
// another surface when it belongs to another object or to another connected piece of the same object's mesh
// (GBufferSample::surface): a leaf card seen in front of another of the same tree.
inline constexpr int kTruthEdgeMargin = 2;
// A pixel is rendered in shadow when less than half of the light gets through.
inline constexpr float kShadowedBelow = 0.5f;

// What the comparison concluded at a pixel.
enum class TruthVerdict : std::uint8_t {
    NotCompared, // background, facing away from the light, not receiving
    Undecided, // truly lit or shadowed, but the shadow map has no say there
    NearEdge, // within kTruthEdgeMargin of a change of class or surface, or near a shadow edge in the light's view
    LitRight,
    ShadowedRight,
    Acne, // truly lit, rendered in shadow
    Leak, // truly shadowed, rendered lit
    Dithered, // truly behind dithered casters only, away from edges: compared on average (TruthComparison::dithered)
};

// The pixels of one ground-truth class: compared ones, and those left out (and why).
struct TruthClassFigures {
    std::size_t compared = 0;
    std::size_t right = 0;
    std::size_t nearEdges = 0;
    std::size_t undecided = 0;

    // 1 for an empty class: none of its pixels is wrong (`compared` says there were none).
    double share() const { return compared == 0 ? 1.0 : double(right) / double(compared); }
};

// The pixels behind dithered casters only, away from edges and where the shadow map decides: the light a correct
// map lets through them on average (1 - LightVisibilityMask::ditherCoverage) and the light it did.
struct DitheredFigures {
    std::size_t compared = 0;
    double expectedLitSum = 0.0;
    double renderedLitSum = 0.0;

    // Mean expected visibility over the compared pixels behind dithered casters.
    double expectedLit() const { return compared == 0 ? 0.0 : expectedLitSum / double(compared); }
    // Mean rendered visibility over the same pixels.
    double renderedLit() const { return compared == 0 ? 0.0 : renderedLitSum / double(compared); }
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
    DitheredFigures dithered;

    // Pixels judged, lit and shadowed.
    std::size_t compared() const { return lit.compared + shadowed.compared; }
    // Truly lit pixels rendered dark.
    std::size_t acne() const { return lit.compared - lit.right; }
    // Truly shadowed pixels rendered lit.
    std::size_t leaks() const { return shadowed.compared - shadowed.right; }
    // Of all compared pixels, the share rendered right (1 when none was compared, as share()).
    double agreement() const { return compared() == 0 ? 1.0 : double(lit.right + shadowed.right) / double(compared()); }
    // The verdict of pixel (x, y), row 0 at the top.
    TruthVerdict at(std::uint32_t x, std::uint32_t y) const { return verdicts[std::size_t(y) * width + x]; }
};

// Shadow edges as a shadow map sees them. A map of texel size s whose filter reaches f texels around the lookup
// and whose normal offset moves the lookup by up to b texels may place an edge anywhere within (f + b + 1/2) s of
// the exact one, however many pixels that covers on screen (many, where light grazes a receiver). A sample is
// near a shadow edge when its ray-cast visibility differs at one of 8 points around it on its tangent plane
// whose projections across the light's rays lie radii[sample] (world units, 0: none) from its own, in the directions
// of a square's sides and diagonals (lifted off the plane by a tenth of their distance along it, over creases of
// up to 5 degrees). A sample whose tangent plane is within 3 degrees of the light's rays is
// near an edge. The points' visibility is a class (visibilityOf), so that a dithered shadow's outline is an edge too.
// Returns 1 for those samples; 0 elsewhere and for samples neither truly lit nor shadowed. Throws
// std::invalid_argument unless there is one radius per sample.
std::vector<std::uint8_t> traceShadowEdges(const RayCaster& shadowRays, const CpuGBuffer& gbuffer,
                                           const LightVisibilityMask& truth, const ShadowRayFrom& rayFrom,
                                           const std::vector<float>& radii, const TraceProgress& progress = {});

// `shadowEdges` (traceShadowEdges, or empty for none) adds its samples to the edges left out. Throws
// std::invalid_argument when the pictures differ in size.
TruthComparison compareWithTruth(const CpuGBuffer& gbuffer, const LightVisibilityMask& truth,
                                 const RenderedVisibility& rendered, const std::vector<std::uint8_t>& shadowEdges = {},
                                 int edgeMargin = kTruthEdgeMargin);

// Where a correct shadow map's lookup for one pixel reads: the lookup point (world, the receiver moved by the
// normal offset) and the radius across the light's rays (world units) that its filter and rasterisation reach;
// radius 0 for none.
struct LookupFootprint {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};

// Disagreements (acne, leaks) confirmed against the footprint of the correct lookup. The ring of traceShadowEdges
// misses features smaller than the gaps between its 8 points (a hole between leaves a texel wide, a leaf's tip),
// which a shadow map resolves only to its texel: an acne or leak pixel whose ray-cast visibility differs anywhere in
// footprints[pixel] (its centre and kFootprintRings rings filling it) is a resolution limit, not a fault, and becomes
// NearEdge, leaving the compared figures of its class. A fault that moves the lookup (a larger normal bias) or drops
// a caster leaves the correct footprint uniform and stays counted. The footprint is traced only where the verdict is
// wrong (the ring's 8 rays per pixel are the price of every pixel), so right pixels near such small features stay
// compared: the agreement shares can count a few more right pixels than a dense test everywhere, never more wrong
// ones. Throws std::invalid_argument unless there are one footprint and one G-buffer sample per verdict.
inline constexpr int kFootprintRings = 4;
void confirmDisagreements(TruthComparison& comparison, const RayCaster& shadowRays, const CpuGBuffer& gbuffer,
                          const LightVisibilityMask& truth, const ShadowRayFrom& rayFrom,
                          const std::vector<LookupFootprint>& footprints);

// Peter-panning: the largest distance along the light from a leak pixel to the surface that truly shadows it,
// in shadow-map texels at that pixel (`texelSize(position)`, world units). Leaks farther than
// `contactTexels` from their blocker are misplaced shadow edges (counted in TruthComparison::leaks), not gaps at
// a contact. 0 without leaks near a contact.
inline constexpr float kContactTexels = 8.0f;
float contactGapTexels(const TruthComparison& comparison, const CpuGBuffer& gbuffer, const RayCaster& shadowRays,
                       const ShadowRayFrom& rayFrom, const std::function<float(glm::vec3)>& texelSize,
                       float contactTexels = kContactTexels);

// Contact gaps, what contact shadows (shadows.contact) are for: pixels the ray cast finds shadowed by a surface
// within `reach` (world units) of the receiver along its shadow ray, which a march of that length towards the light
// can find (`shadowed`), and those of them the renderer draws lit (`gaps`). Unlike the comparison it keeps pixels
// near shadow edges, which is where such gaps are (a gap at a caster's foot is always within a filter's reach of
// the caster's shadow edge); it leaves out only pixels the maps do not decide, pixels neither truly lit nor truly
// shadowed (dithered casters), and grazing receivers (the light within 3 degrees of their plane, where the ray
// cast's answer turns on the smallest difference of normal). Throws std::invalid_argument when the pictures differ
// in size.
struct ContactGapFigures {
    std::size_t shadowed = 0;
    std::size_t gaps = 0;
};
ContactGapFigures contactGapPixels(const CpuGBuffer& gbuffer, const LightVisibilityMask& truth,
                                   const RenderedVisibility& rendered, const RayCaster& shadowRays,
                                   const ShadowRayFrom& rayFrom, float reach);

} // namespace penumbra::truth
