#include "penumbra/shadows/DepthFit.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra::shadows {
namespace {

float floorToGrid(float depth, std::uint32_t steps)
{
    const float step = depthFitStep(depth, steps);
    return std::floor(depth / step) * step;
}

float ceilToGrid(float depth, std::uint32_t steps)
{
    const float step = depthFitStep(depth, steps);
    return std::ceil(depth / step) * step;
}

} // namespace

float depthFitStep(float depth, std::uint32_t stepsPerOctave)
{
    return std::exp2(std::floor(std::log2(depth))) / static_cast<float>(stepsPerOctave);
}

ViewDepthRange quantizeViewDepthRange(ViewDepthRange measured, std::optional<ViewDepthRange> kept,
                                      std::uint32_t stepsPerOctave, float hysteresisSteps)
{
    if (stepsPerOctave == 0 || !(measured.nearDepth > 0.0f) || !(measured.farDepth > 0.0f))
        return measured;
    ViewDepthRange fitted{floorToGrid(measured.nearDepth, stepsPerOctave),
                          ceilToGrid(measured.farDepth, stepsPerOctave)};
    if (!kept)
        return fitted;
    // Sample distribution shadow maps (Lauritzen, Salvi and Lefohn, I3D 2011) refit every frame; the kept range is
    // what keeps the splits, and with them every tile's texel size, still while the visible depths barely move.
    const float reach = 1.0f + hysteresisSteps;
    const float nearStep = depthFitStep(kept->nearDepth, stepsPerOctave);
    if (measured.nearDepth >= kept->nearDepth && measured.nearDepth < kept->nearDepth + reach * nearStep)
        fitted.nearDepth = kept->nearDepth;
    const float farStep = depthFitStep(kept->farDepth, stepsPerOctave);
    if (measured.farDepth <= kept->farDepth && measured.farDepth > kept->farDepth - reach * farStep)
        fitted.farDepth = kept->farDepth;
    return fitted;
}

CascadeSplits depthFitSplits(ViewDepthRange fitted, float cameraNear, float cameraFar, float maxDistance,
                             std::uint32_t cascadeCount, glm::vec3 ratios, std::uint32_t stepsPerOctave)
{
    const float shadowFar = std::max(std::min(maxDistance, cameraFar), cameraNear);
    const float nearDepth = std::clamp(fitted.nearDepth, cameraNear, shadowFar);
    const float farDepth = std::clamp(fitted.farDepth, nearDepth, shadowFar);
    CascadeSplits splits;
    splits.count = cascadeCount;
    splits.distances[0] = nearDepth;
    for (std::uint32_t i = 1; i < cascadeCount; ++i) {
        float split = ratios[static_cast<int>(i - 1)] * farDepth;
        if (stepsPerOctave > 0 && split > 0.0f) {
            const float step = depthFitStep(split, stepsPerOctave);
            split = std::round(split / step) * step;
        }
        splits.distances[i] = std::clamp(split, splits.distances[i - 1], farDepth);
    }
    splits.distances[cascadeCount] = farDepth;
    return splits;
}

} // namespace penumbra::shadows
