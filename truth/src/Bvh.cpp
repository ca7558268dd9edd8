#include "Bvh.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <array>

namespace penumbra::truth {
namespace {

constexpr int kBinCount = 16;
constexpr std::uint32_t kMinLeafSize = 2; // smaller ranges become leaves without a cost estimate
constexpr std::uint32_t kMaxLeafSize = 16; // larger ranges are split even when SAH calls it a loss
// Cost of visiting a node relative to one triangle test; Moller-Trumbore and a slab test
// cost about the same.
constexpr float kTraversalCost = 1.0f;

float surfaceArea(const scene::Bounds& bounds)
{
    if (bounds.empty())
        return 0.0f;
    const glm::vec3 d = bounds.size();
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
}

struct Split {
    int axis = -1;
    int bin = 0; // primitives in bins [0, bin) go left
    float cost = 0.0f;
};

class Builder {
public:
    Builder(std::span<const scene::Bounds> bounds, Bvh& bvh) : bounds_(bounds), bvh_(bvh)
    {
        centroids_.reserve(bounds.size());
        for (const scene::Bounds& b : bounds)
            centroids_.push_back(b.center());
    }

    void build(std::uint32_t node, std::uint32_t first, std::uint32_t count, std::uint32_t depth)
    {
        scene::Bounds nodeBounds;
        scene::Bounds centroidBounds;
        for (std::uint32_t i = first; i < first + count; ++i) {
            nodeBounds.extend(bounds_[bvh_.order[i]]);
            centroidBounds.extend(centroids_[bvh_.order[i]]);
        }
        bvh_.nodes[node] = {nodeBounds.min, first, nodeBounds.max, count};
        if (count <= kMinLeafSize || depth == kBvhMaxDepth)
            return;

        std::uint32_t middle = first + count / 2;
        const Split split = bestSplit(first, count, centroidBounds);
        if (split.axis >= 0) {
            const float area = surfaceArea(nodeBounds);
            if (count <= kMaxLeafSize && kTraversalCost * area + split.cost >= static_cast<float>(count) * area)
                return;
            const auto begin = bvh_.order.begin() + first;
            middle = static_cast<std::uint32_t>(
                std::partition(begin, begin + count,
                               [&](std::uint32_t p) { return binOf(p, split.axis, centroidBounds) < split.bin; }) -
                bvh_.order.begin());
        } else if (count <= kMaxLeafSize) {
            return; // all centroids coincide: no split separates them, and the leaf is small enough
        }
        // else: coincident centroids in a big range; halving by index still bounds the leaf size.

        const auto left = static_cast<std::uint32_t>(bvh_.nodes.size());
        bvh_.nodes.resize(bvh_.nodes.size() + 2);
        bvh_.nodes[node].first = left;
        bvh_.nodes[node].count = 0;
        build(left, first, middle - first, depth + 1);
        build(left + 1, middle, first + count - middle, depth + 1);
    }

private:
    int binOf(std::uint32_t primitive, int axis, const scene::Bounds& centroidBounds) const
    {
        const float extent = centroidBounds.max[axis] - centroidBounds.min[axis];
        const float relative = (centroids_[primitive][axis] - centroidBounds.min[axis]) / extent;
        return std::min(kBinCount - 1, static_cast<int>(relative * kBinCount));
    }

    // Binned SAH over all three axes; cost is kept unnormalised (areas times counts) and
    // compared with the leaf cost in the same units.
    Split bestSplit(std::uint32_t first, std::uint32_t count, const scene::Bounds& centroidBounds) const
    {
        Split best;
        for (int axis = 0; axis < 3; ++axis) {
            if (!(centroidBounds.max[axis] > centroidBounds.min[axis]))
                continue;
            std::array<scene::Bounds, kBinCount> bins{};
            std::array<std::uint32_t, kBinCount> counts{};
            for (std::uint32_t i = first; i < first + count; ++i) {
                const std::uint32_t p = bvh_.order[i];
                const int bin = binOf(p, axis, centroidBounds);
                bins[bin].extend(bounds_[p]);
                ++counts[bin];
            }
            // Right-to-left sweep stores the right side's cost per split plane.
            std::array<float, kBinCount> rightCost{};
            scene::Bounds right;
            std::uint32_t rightCount = 0;
            for (int bin = kBinCount - 1; bin > 0; --bin) {
                right.extend(bins[bin]);
                rightCount += counts[bin];
                rightCost[bin] = surfaceArea(right) * static_cast<float>(rightCount);
            }
            scene::Bounds left;
            std::uint32_t leftCount = 0;
            for (int bin = 1; bin < kBinCount; ++bin) {
                left.extend(bins[bin - 1]);
                leftCount += counts[bin - 1];
                if (leftCount == 0 || leftCount == count)
                    continue;
                const float cost = surfaceArea(left) * static_cast<float>(leftCount) + rightCost[bin];
                if (best.axis < 0 || cost < best.cost)
                    best = {axis, bin, cost};
            }
        }
        return best;
    }

    std::span<const scene::Bounds> bounds_;
    std::vector<glm::vec3> centroids_;
    Bvh& bvh_;
};

} // namespace

Bvh buildBvh(std::span<const scene::Bounds> primitiveBounds)
{
    Bvh bvh;
    if (primitiveBounds.empty())
        return bvh;
    bvh.order.resize(primitiveBounds.size());
    for (std::uint32_t i = 0; i < bvh.order.size(); ++i)
        bvh.order[i] = i;
    // A binary tree over n primitives has at most 2n - 1 nodes.
    bvh.nodes.reserve(2 * primitiveBounds.size());
    bvh.nodes.resize(1);
    Builder(primitiveBounds, bvh).build(0, 0, static_cast<std::uint32_t>(primitiveBounds.size()), 0);
    return bvh;
}

} // namespace penumbra::truth
