#include "penumbra/shadows/TentFilter.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra::shadows {
namespace {

// Cumulative integral of the unit-area tent of half width h (height 1 / h) from -h to x.
float tentCdf(float x, float h)
{
    const float u = std::clamp(x / h, -1.0f, 1.0f);
    return u < 0.0f ? 0.5f * (1.0f + u) * (1.0f + u) : 1.0f - 0.5f * (1.0f - u) * (1.0f - u);
}

} // namespace

TexelWeights tentTexelWeights(ShadowFilter filter, float centre)
{
    TexelWeights w;
    if (filter == ShadowFilter::PCF2x2) {
        // A 1-texel box over the texels: the two around the centre, bilinear fractions.
        w.first = static_cast<int>(std::floor(centre - 0.5f));
        const float f = centre - 0.5f - static_cast<float>(w.first);
        w.count = 2;
        w.weights[0] = 1.0f - f;
        w.weights[1] = f;
        return w;
    }
    const int n = filterSize(filter);
    const float h = 0.5f * static_cast<float>(n);
    // The tent's support [c - n/2, c + n/2] lies in the n + 1 texels around the nearest texel corner.
    const int corner = static_cast<int>(std::floor(centre + 0.5f));
    w.first = corner - (n + 1) / 2;
    w.count = n + 1;
    for (int k = 0; k < w.count; ++k) {
        const float left = static_cast<float>(w.first + k) - centre;
        w.weights[static_cast<std::size_t>(k)] = tentCdf(left + 1.0f, h) - tentCdf(left, h);
    }
    return w;
}

ShadowTaps tentFilterTaps(ShadowFilter filter, glm::vec2 uv, glm::vec2 textureSize)
{
    ShadowTaps taps;
    if (filter == ShadowFilter::PCF2x2) {
        taps.taps[0] = {uv, 1.0f};
        taps.count = 1;
        return taps;
    }
    const glm::vec2 texel = uv * textureSize;
    const TexelWeights axes[2] = {tentTexelWeights(filter, texel.x), tentTexelWeights(filter, texel.y)};
    // Per axis, texel pairs (2p, 2p + 1) become one tap at the pair's weighted position.
    float position[2][4];
    float weight[2][4];
    const int pairs = axes[0].count / 2;
    for (int axis = 0; axis < 2; ++axis) {
        for (int p = 0; p < pairs; ++p) {
            const float a = axes[axis].weights[static_cast<std::size_t>(2 * p)];
            const float b = axes[axis].weights[static_cast<std::size_t>(2 * p + 1)];
            const float sum = a + b;
            const float firstCentre = static_cast<float>(axes[axis].first + 2 * p) + 0.5f;
            position[axis][p] = firstCentre + (sum > 0.0f ? b / sum : 0.5f);
            weight[axis][p] = sum;
        }
    }
    for (int py = 0; py < pairs; ++py)
        for (int px = 0; px < pairs; ++px)
            taps.taps[static_cast<std::size_t>(taps.count++)] = {glm::vec2(position[0][px], position[1][py]) /
                                                                     textureSize,
                                                                 weight[0][px] * weight[1][py]};
    return taps;
}

} // namespace penumbra::shadows
