#pragma once

#include "penumbra/shadows/CascadeSplits.hpp"

#include <cstdint>
#include <optional>

namespace penumbra::shadows {

// The view depths of the surfaces the camera sees, nearest and farthest (a reduction of the depth prepass).
struct ViewDepthRange {
    float nearDepth = 0.0f;
    float farDepth = 0.0f;

    bool operator==(const ViewDepthRange&) const = default;
};

// The grid step of view depth `depth` with `stepsPerOctave` steps per power of two: 2^floor(log2 depth) / steps,
// so that a step is between 1 / steps and 2 / steps of the depth itself.
float depthFitStep(float depth, std::uint32_t stepsPerOctave);

// The range depthFit fits its cascades to, from the measured one and the range the last frame kept. The near depth
// floors and the far depth ceils onto depthFitStep's grid, so the result holds the measured range; a kept range is
// kept while it still holds the measured one and neither end lies more than 1 + hysteresisSteps of its steps inside
// it (hysteresis: depths that wander about a grid line do not flip the fit each frame). stepsPerOctave 0 leaves the
// range unquantized, as measured. Depths at or below 0 are taken as given (nothing to quantize).
ViewDepthRange quantizeViewDepthRange(ViewDepthRange measured, std::optional<ViewDepthRange> kept,
                                      std::uint32_t stepsPerOctave, float hysteresisSteps);

// depthFit's splits: cascadeSplits with the fitted range's far depth for the shadow distance and its near depth for the
// camera's near plane, d_0 = near, d_i = ratio_{i-1} far (at least near), d_count = far, with near and far clamped to
// [cameraNear, shadowFar] (shadowFar = min(maxDistance, cameraFar)); the inner splits rounded to depthFitStep's grid
// (stepsPerOctave 0: not rounded) and kept in order. Every slice is then within the stable fit's of the same
// distance, so no sphere is larger.
CascadeSplits depthFitSplits(ViewDepthRange fitted, float cameraNear, float cameraFar, float maxDistance,
                             std::uint32_t cascadeCount, glm::vec3 ratios, std::uint32_t stepsPerOctave);

} // namespace penumbra::shadows
