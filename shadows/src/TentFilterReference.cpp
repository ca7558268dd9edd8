#include "penumbra/shadows/TentFilterReference.hpp"

#include "penumbra/shadows/TentFilter.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra::shadows {
namespace {

bool passes(rhi::CompareOp op, float reference, float stored)
{
    switch (op) {
    case rhi::CompareOp::Never:
        return false;
    case rhi::CompareOp::Less:
        return reference < stored;
    case rhi::CompareOp::LessOrEqual:
        return reference <= stored;
    case rhi::CompareOp::Equal:
        return reference == stored;
    case rhi::CompareOp::Greater:
        return reference > stored;
    case rhi::CompareOp::GreaterOrEqual:
        return reference >= stored;
    case rhi::CompareOp::NotEqual:
        return reference != stored;
    case rhi::CompareOp::Always:
        return true;
    }
    return false;
}

// Sum of weight * value over the summed weights: weights that miss 1 by float rounding still give
// exactly 1 or 0 over a constant field, since both sums then take the same steps.
struct WeightedSum {
    float weighted = 0.0f;
    float total = 0.0f;

    void add(float weight, float value)
    {
        weighted += weight * value;
        total += weight;
    }
    float mean() const { return weighted / total; }
};

glm::vec2 gridSize(const ShadowDepthGrid& grid)
{
    return {static_cast<float>(grid.width), static_cast<float>(grid.height)};
}

} // namespace

float ShadowDepthGrid::at(int x, int y) const
{
    const int cx = std::clamp(x, 0, static_cast<int>(width) - 1);
    const int cy = std::clamp(y, 0, static_cast<int>(height) - 1);
    return depths[static_cast<std::size_t>(cy) * width + static_cast<std::size_t>(cx)];
}

float compareTexel(const ShadowDepthGrid& grid, int x, int y, float receiverDepth, rhi::CompareOp op)
{
    return passes(op, receiverDepth, grid.at(x, y)) ? 1.0f : 0.0f;
}

float bilinearCompare(const ShadowDepthGrid& grid, glm::vec2 uv, float receiverDepth, rhi::CompareOp op)
{
    const glm::vec2 p = uv * gridSize(grid) - 0.5f;
    const glm::vec2 base = glm::floor(p);
    const glm::vec2 f = p - base;
    const int x = static_cast<int>(base.x);
    const int y = static_cast<int>(base.y);
    WeightedSum sum;
    sum.add((1.0f - f.x) * (1.0f - f.y), compareTexel(grid, x, y, receiverDepth, op));
    sum.add(f.x * (1.0f - f.y), compareTexel(grid, x + 1, y, receiverDepth, op));
    sum.add((1.0f - f.x) * f.y, compareTexel(grid, x, y + 1, receiverDepth, op));
    sum.add(f.x * f.y, compareTexel(grid, x + 1, y + 1, receiverDepth, op));
    return sum.mean();
}

float filterShadowReference(const ShadowDepthGrid& grid, ShadowFilter filter, glm::vec2 uv, float receiverDepth,
                            rhi::CompareOp op)
{
    const glm::vec2 texel = uv * gridSize(grid);
    const TexelWeights wx = tentTexelWeights(filter, texel.x);
    const TexelWeights wy = tentTexelWeights(filter, texel.y);
    WeightedSum sum;
    for (int j = 0; j < wy.count; ++j)
        for (int i = 0; i < wx.count; ++i)
            sum.add(wx.weights[static_cast<std::size_t>(i)] * wy.weights[static_cast<std::size_t>(j)],
                    compareTexel(grid, wx.first + i, wy.first + j, receiverDepth, op));
    return sum.mean();
}

float filterShadowWithTaps(const ShadowDepthGrid& grid, ShadowFilter filter, glm::vec2 uv, float receiverDepth,
                           rhi::CompareOp op)
{
    const ShadowTaps taps = tentFilterTaps(filter, uv, gridSize(grid));
    WeightedSum sum;
    for (const ShadowTap& tap : taps.view())
        sum.add(tap.weight, bilinearCompare(grid, tap.uv, receiverDepth, op));
    return sum.mean();
}

} // namespace penumbra::shadows
