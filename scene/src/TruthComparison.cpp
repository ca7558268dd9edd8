#include "penumbra/scene/TruthComparison.hpp"

#include <algorithm>
#include <stdexcept>

namespace penumbra::scene {
namespace {

bool nearEdge(const CpuGBuffer& gbuffer, const LightVisibilityMask& truth, std::uint32_t x, std::uint32_t y,
              int margin)
{
    for (int dy = -margin; dy <= margin; ++dy)
        for (int dx = -margin; dx <= margin; ++dx) {
            const int nx = int(x) + dx, ny = int(y) + dy;
            if (nx < 0 || ny < 0 || nx >= int(truth.width) || ny >= int(truth.height))
                return true;
            if (truth.at(nx, ny) != truth.at(x, y) || gbuffer.at(nx, ny).object != gbuffer.at(x, y).object)
                return true;
        }
    return false;
}

} // namespace

TruthComparison compareWithTruth(const CpuGBuffer& gbuffer, const LightVisibilityMask& truth,
                                 const RenderedVisibility& rendered, int edgeMargin)
{
    if (gbuffer.width != truth.width || gbuffer.height != truth.height || rendered.width != truth.width ||
        rendered.height != truth.height)
        throw std::invalid_argument("compareWithTruth: the G-buffer, the ray-cast visibility and the rendered "
                                    "visibility must have the same size");
    TruthComparison c{truth.width, truth.height,
                      std::vector<TruthVerdict>(truth.pixels.size(), TruthVerdict::NotCompared), {}, {}};
    for (std::uint32_t y = 0; y < truth.height; ++y)
        for (std::uint32_t x = 0; x < truth.width; ++x) {
            const std::size_t i = std::size_t(y) * truth.width + x;
            const LightVisibility expected = truth.pixels[i];
            if (expected != LightVisibility::Lit && expected != LightVisibility::Shadowed)
                continue;
            const bool shadowedTruly = expected == LightVisibility::Shadowed;
            TruthClassFigures& figures = shadowedTruly ? c.shadowed : c.lit;
            TruthVerdict& verdict = c.verdicts[i];
            if (!rendered.decided[i]) {
                ++figures.undecided;
                verdict = TruthVerdict::Undecided;
            } else if (nearEdge(gbuffer, truth, x, y, edgeMargin)) {
                ++figures.nearEdges;
                verdict = TruthVerdict::NearEdge;
            } else {
                ++figures.compared;
                const bool shadowedRendered = rendered.lit[i] < kShadowedBelow;
                figures.right += shadowedRendered == shadowedTruly;
                verdict = shadowedTruly ? (shadowedRendered ? TruthVerdict::ShadowedRight : TruthVerdict::Leak)
                                        : (shadowedRendered ? TruthVerdict::Acne : TruthVerdict::LitRight);
            }
        }
    return c;
}

float contactGapTexels(const TruthComparison& comparison, const CpuGBuffer& gbuffer, const RayCaster& shadowRays,
                       const std::function<ShadowRay(const GBufferSample&)>& rayOf,
                       const std::function<float(glm::vec3)>& texelSize, float contactTexels)
{
    float gap = 0.0f;
    for (std::size_t i = 0; i < comparison.verdicts.size(); ++i) {
        if (comparison.verdicts[i] != TruthVerdict::Leak)
            continue;
        const GBufferSample& sample = gbuffer.samples[i];
        const ShadowRay ray = rayOf(sample);
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

} // namespace penumbra::scene
