#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

namespace penumbra::shadows {

// View depths bounding each cascade: cascade i covers [distances[i], distances[i + 1]].
struct CascadeSplits {
    std::array<float, 5> distances{};
    std::uint32_t count = 0;

    // View distance where cascade `cascade` starts.
    float nearOf(std::uint32_t cascade) const { return distances[cascade]; }
    // View distance where cascade `cascade` ends.
    float farOf(std::uint32_t cascade) const { return distances[cascade + 1]; }
};

// d_0 = near, d_i = ratio_{i-1} * shadowFar (0 < i < count), d_count = shadowFar = min(maxDistance, far);
// each clamped to [near, shadowFar] so the slices stay ordered.
CascadeSplits cascadeSplits(float cameraNear, float cameraFar, float maxDistance, std::uint32_t cascadeCount,
                            glm::vec3 ratios);

} // namespace penumbra::shadows
