#include "penumbra/shadows/CascadeSplits.hpp"

#include <algorithm>

namespace penumbra::shadows {

CascadeSplits cascadeSplits(float cameraNear, float cameraFar, float maxDistance, std::uint32_t cascadeCount,
                            glm::vec3 ratios)
{
    const float shadowFar = std::max(std::min(maxDistance, cameraFar), cameraNear);
    CascadeSplits splits;
    splits.count = cascadeCount;
    splits.distances[0] = cameraNear;
    for (std::uint32_t i = 1; i < cascadeCount; ++i)
        splits.distances[i] = std::clamp(ratios[static_cast<int>(i - 1)] * shadowFar, cameraNear, shadowFar);
    splits.distances[cascadeCount] = shadowFar;
    return splits;
}

} // namespace penumbra::shadows
