#include "penumbra/truth/TruthComparison.hpp"

#include "ParallelRows.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace penumbra::truth {
namespace {

bool nearEdge(const CpuGBuffer& gbuffer, const LightVisibilityMask& truth, std::uint32_t x, std::uint32_t y, int margin)
{
    for (int dy = -margin; dy <= margin; ++dy)
        for (int dx = -margin; dx <= margin; ++dx) {
            const int nx = int(x) + dx, ny = int(y) + dy;
            if (nx < 0 || ny < 0 || nx >= int(truth.width) || ny >= int(truth.height))
                return true;
            const GBufferSample& here = gbuffer.at(x, y);
            const GBufferSample& there = gbuffer.at(nx, ny);
            if (truth.at(nx, ny) != truth.at(x, y) || there.object != here.object || there.surface != here.surface)
                return true;
        }
    return false;
}

// Two unit vectors perpendicular to `d` and to each other.
std::array<glm::vec3, 2> acrossRay(glm::vec3 d)
{
    const glm::vec3 helper = std::abs(d.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 u = glm::normalize(glm::cross(helper, d));
    return {u, glm::cross(d, u)};
}

// tan(5.7 degrees): how far a tangent-plane step is lifted off the plane, per unit of its length.
constexpr float kCreaseLift = 0.1f;

// sin(3 degrees): below it a tangent-plane step that moves radius across the rays runs 19 radii along the surface.
constexpr float kGrazing = 0.052f;

// Whether a shadow ray's class differs from `expected`.
bool differs(const RayCaster& shadowRays, const ShadowRay& ray, LightVisibility expected)
{
    return visibilityOf(shadowRays.occlusion(ray.origin, ray.direction, ray.maxDistance)) != expected;
}

bool nearShadowEdge(const RayCaster& shadowRays, const GBufferSample& sample, LightVisibility expected,
                    const ShadowRayFrom& rayFrom, float radius)
{
    const glm::vec3 towardsLight = rayFrom(shadowRayOrigin(sample)).direction;
    const float facing = glm::dot(towardsLight, sample.normal);
    if (facing < kGrazing)
        return true;
    const std::array<glm::vec3, 2> across = acrossRay(towardsLight);
    for (int k = 0; k < 8; ++k) {
        const float angle = 0.25f * 3.14159265f * static_cast<float>(k);
        const glm::vec3 a = radius * (std::cos(angle) * across[0] + std::sin(angle) * across[1]);
        // Along the tangent plane: a plus the step along the ray that brings it back onto the plane; lifted off it
        // by a tenth of the step, so that the point stays above a receiver that bends away by up to 5 degrees
        // (a heightfield's creases) instead of testing the receiver's own underside.
        const glm::vec3 step = a - towardsLight * (glm::dot(a, sample.normal) / facing);
        const float lift = kShadowRayOffset + kCreaseLift * glm::length(step);
        if (differs(shadowRays, rayFrom(sample.position + step + lift * sample.normal), expected))
            return true;
    }
    return false;
}

// Whether the ray-cast visibility differs from `shadowed` anywhere in `footprint` of `sample`'s lookup: at its centre
// and on kFootprintRings rings filling it (ring j at radius * j / kFootprintRings, of 8 j points), across the light's
// rays. A point below the receiver's plane (lifted as nearShadowEdge lifts) moves along its ray onto it, so that
// the receiver does not shadow itself.
bool footprintHasEdge(const RayCaster& shadowRays, const GBufferSample& sample, LightVisibility expected,
                      const ShadowRayFrom& rayFrom, const LookupFootprint& footprint)
{
    const glm::vec3 towardsLight = rayFrom(shadowRayOrigin(sample)).direction;
    const float facing = glm::dot(towardsLight, sample.normal);
    if (facing < kGrazing)
        return true;
    const std::array<glm::vec3, 2> across = acrossRay(towardsLight);
    // The points first, then the rays: GCC 12 -O2 stops with an internal error (compute_live_loop_exits) on an
    // early return from the nested loops.
    std::vector<glm::vec3> points;
    for (int ring = 0; ring <= kFootprintRings; ++ring)
        for (int k = 0; k < std::max(8 * ring, 1); ++k) {
            const float angle = 0.25f * 3.14159265f * static_cast<float>(k) / static_cast<float>(std::max(ring, 1));
            const float distance = footprint.radius * static_cast<float>(ring) / static_cast<float>(kFootprintRings);
            glm::vec3 point = footprint.centre + distance * (std::cos(angle) * across[0] + std::sin(angle) * across[1]);
            const float lift = kShadowRayOffset + kCreaseLift * glm::length(point - sample.position);
            const float height = glm::dot(point - sample.position, sample.normal);
            if (height < lift)
                point += towardsLight * ((lift - height) / facing);
            points.push_back(point);
        }
    return std::any_of(points.begin(), points.end(),
                       [&](const glm::vec3& point) { return differs(shadowRays, rayFrom(point), expected); });
}

} // namespace

std::vector<std::uint8_t> traceShadowEdges(const RayCaster& shadowRays, const CpuGBuffer& gbuffer,
                                           const LightVisibilityMask& truth, const ShadowRayFrom& rayFrom,
                                           const std::vector<float>& radii, const TraceProgress& progress)
{
    if (radii.size() != gbuffer.samples.size())
        throw std::invalid_argument("traceShadowEdges: one radius per G-buffer sample");
    std::vector<std::uint8_t> edges(gbuffer.samples.size(), 0);
    forEachRow(
        gbuffer.height,
        [&](std::uint32_t y) {
            for (std::size_t i = std::size_t(y) * gbuffer.width; i < std::size_t(y + 1) * gbuffer.width; ++i) {
                const LightVisibility v = truth.pixels[i];
                if (v != LightVisibility::Lit && v != LightVisibility::Shadowed)
                    continue;
                const float r = radii[i];
                edges[i] = r > 0.0f && nearShadowEdge(shadowRays, gbuffer.samples[i], v, rayFrom, r);
            }
        },
        progress);
    return edges;
}

TruthComparison compareWithTruth(const CpuGBuffer& gbuffer, const LightVisibilityMask& truth,
                                 const RenderedVisibility& rendered, const std::vector<std::uint8_t>& shadowEdges,
                                 int edgeMargin)
{
    if (gbuffer.width != truth.width || gbuffer.height != truth.height || rendered.width != truth.width ||
        rendered.height != truth.height || (!shadowEdges.empty() && shadowEdges.size() != truth.pixels.size()))
        throw std::invalid_argument("compareWithTruth: the G-buffer, the ray-cast visibility and the rendered "
                                    "visibility must have the same size");
    TruthComparison c{
        truth.width, truth.height, std::vector<TruthVerdict>(truth.pixels.size(), TruthVerdict::NotCompared),
        {},          {},           {},
        {}};
    for (std::uint32_t y = 0; y < truth.height; ++y)
        for (std::uint32_t x = 0; x < truth.width; ++x) {
            const std::size_t i = std::size_t(y) * truth.width + x;
            const LightVisibility expected = truth.pixels[i];
            if (expected == LightVisibility::Dithered && rendered.decided[i] &&
                !nearEdge(gbuffer, truth, x, y, edgeMargin)) {
                ++c.dithered.compared;
                c.dithered.expectedLitSum += 1.0 - double(truth.ditherCoverage.at(i));
                c.dithered.renderedLitSum += double(rendered.lit[i]);
                c.verdicts[i] = TruthVerdict::Dithered;
            }
            if (expected != LightVisibility::Lit && expected != LightVisibility::Shadowed)
                continue;
            const bool shadowedTruly = expected == LightVisibility::Shadowed;
            TruthClassFigures& figures = shadowedTruly ? c.shadowed : c.lit;
            TruthVerdict& verdict = c.verdicts[i];
            if (!rendered.decided[i]) {
                ++figures.undecided;
                verdict = TruthVerdict::Undecided;
            } else if ((!shadowEdges.empty() && shadowEdges[i]) || nearEdge(gbuffer, truth, x, y, edgeMargin)) {
                ++figures.nearEdges;
                verdict = TruthVerdict::NearEdge;
            } else {
                ++figures.compared;
                const bool shadowedRendered = rendered.lit[i] < kShadowedBelow;
                figures.right += shadowedRendered == shadowedTruly;
                if (shadowedTruly && !truth.blockers.empty() && truth.blockers[i] != kNoObject) {
                    TruthClassFigures& caster = c.shadowedBy[truth.blockers[i]];
                    ++caster.compared;
                    caster.right += shadowedRendered;
                }
                verdict = shadowedTruly ? (shadowedRendered ? TruthVerdict::ShadowedRight : TruthVerdict::Leak)
                                        : (shadowedRendered ? TruthVerdict::Acne : TruthVerdict::LitRight);
            }
        }
    return c;
}

void confirmDisagreements(TruthComparison& comparison, const RayCaster& shadowRays, const CpuGBuffer& gbuffer,
                          const LightVisibilityMask& truth, const ShadowRayFrom& rayFrom,
                          const std::vector<LookupFootprint>& footprints)
{
    if (footprints.size() != comparison.verdicts.size() || gbuffer.samples.size() != comparison.verdicts.size())
        throw std::invalid_argument("confirmDisagreements: one lookup footprint and one G-buffer sample per pixel");
    for (std::size_t i = 0; i < comparison.verdicts.size(); ++i) {
        TruthVerdict& verdict = comparison.verdicts[i];
        const bool leak = verdict == TruthVerdict::Leak;
        if ((!leak && verdict != TruthVerdict::Acne) || footprints[i].radius <= 0.0f ||
            !footprintHasEdge(shadowRays, gbuffer.samples[i], leak ? LightVisibility::Shadowed : LightVisibility::Lit,
                              rayFrom, footprints[i]))
            continue;
        verdict = TruthVerdict::NearEdge;
        TruthClassFigures& figures = leak ? comparison.shadowed : comparison.lit;
        --figures.compared;
        ++figures.nearEdges;
        if (leak && !truth.blockers.empty() && truth.blockers[i] != kNoObject)
            --comparison.shadowedBy[truth.blockers[i]].compared;
    }
}

float contactGapTexels(const TruthComparison& comparison, const CpuGBuffer& gbuffer, const RayCaster& shadowRays,
                       const ShadowRayFrom& rayFrom, const std::function<float(glm::vec3)>& texelSize,
                       float contactTexels)
{
    float gap = 0.0f;
    for (std::size_t i = 0; i < comparison.verdicts.size(); ++i) {
        if (comparison.verdicts[i] != TruthVerdict::Leak)
            continue;
        const GBufferSample& sample = gbuffer.samples[i];
        const ShadowRay ray = rayFrom(shadowRayOrigin(sample));
        const std::optional<Hit> blocker = shadowRays.closestHit(ray.origin, ray.direction, ray.maxDistance);
        const float texel = texelSize(sample.position);
        if (!blocker || texel <= 0.0f)
            continue;
        const float texels = blocker->distance / texel;
        if (texels <= contactTexels)
            gap = std::max(gap, texels);
    }
    return gap;
}

ContactGapFigures contactGapPixels(const CpuGBuffer& gbuffer, const LightVisibilityMask& truth,
                                   const RenderedVisibility& rendered, const RayCaster& shadowRays,
                                   const ShadowRayFrom& rayFrom, float reach)
{
    if (gbuffer.samples.size() != truth.pixels.size() || rendered.lit.size() != truth.pixels.size() ||
        rendered.decided.size() != truth.pixels.size())
        throw std::invalid_argument("contactGapPixels: the G-buffer, the ray-cast visibility and the rendered "
                                    "visibility must have the same size");
    ContactGapFigures figures;
    for (std::size_t i = 0; i < truth.pixels.size(); ++i) {
        if (truth.pixels[i] != LightVisibility::Shadowed || !rendered.decided[i])
            continue;
        const GBufferSample& sample = gbuffer.samples[i];
        const ShadowRay ray = rayFrom(shadowRayOrigin(sample));
        if (glm::dot(ray.direction, sample.normal) < kGrazing ||
            !shadowRays.closestHit(ray.origin, ray.direction, std::min(reach, ray.maxDistance)))
            continue;
        ++figures.shadowed;
        figures.gaps += rendered.lit[i] >= kShadowedBelow ? 1 : 0;
    }
    return figures;
}

} // namespace penumbra::truth
