#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

namespace penumbra::shadows {

// A depth texture on the CPU: row 0 is the top row (v = 0), as in every Penumbra image.
struct ShadowDepthGrid {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<float> depths; // width * height window depths, row by row

    // Texel (x, y) with clamp-to-edge addressing, as the shadow sampler's.
    float at(int x, int y) const;
};

// 1 (lit) where `receiverDepth op stored` holds for texel (x, y), else 0: one nearest comparison.
float compareTexel(const ShadowDepthGrid& grid, int x, int y, float receiverDepth, rhi::CompareOp op);

// The filters below divide the weighted sum of comparisons by the summed weights, so a constant
// field gives exactly 1 or 0 despite float rounding; the shader should do the same.

// What a linear comparison sampler returns, built as the shader builds it where depth formats
// cannot be filtered (lavapipe): 4 nearest comparisons around texture coordinate uv, bilinear weights.
float bilinearCompare(const ShadowDepthGrid& grid, glm::vec2 uv, float receiverDepth, rhi::CompareOp op);

// Reference PCF: every texel's nearest comparison weighted by the analytic filter (tentTexelWeights).
float filterShadowReference(const ShadowDepthGrid& grid, ShadowFilter filter, glm::vec2 uv, float receiverDepth,
                            rhi::CompareOp op);

// The shader's PCF: tentFilterTaps, each read by bilinearCompare.
float filterShadowWithTaps(const ShadowDepthGrid& grid, ShadowFilter filter, glm::vec2 uv, float receiverDepth,
                           rhi::CompareOp op);

} // namespace penumbra::shadows
