#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace penumbra::shadows {

// The draw group of an item that shares its draw with no other.
inline constexpr std::uint32_t kNoDrawGroup = std::numeric_limits<std::uint32_t>::max();

// Items to draw, reordered so that each batch (items of one draw group) is a contiguous range of `items`:
// one instanced draw each.
struct InstanceBatches {
    // A run of items drawn as the instances of one draw.
    struct Batch {
        std::uint32_t first = 0; // into items
        std::uint32_t count = 0;
        // Equal runs.
        bool operator==(const Batch&) const = default;
    };
    std::vector<std::uint32_t> items;
    std::vector<Batch> batches;
};

// Groups `items` by groupOf(item): a batch per group, in the order of each group's first item, its items in their
// given order; each item of kNoDrawGroup is a batch of its own. For draws whose order does not change the picture
// (depth-tested opaque surfaces: the nearest wins whatever the order). Linear in items and groups (a counting sort).
template <typename GroupOf>
InstanceBatches batchByGroup(std::span<const std::uint32_t> items, GroupOf groupOf)
{
    std::uint32_t groups = 0;
    for (const std::uint32_t item : items)
        if (const std::uint32_t group = groupOf(item); group != kNoDrawGroup)
            groups = std::max(groups, group + 1);
    std::vector<std::uint32_t> batchOfGroup(groups, kNoDrawGroup);
    std::vector<std::uint32_t> batchOfItem(items.size());
    InstanceBatches result;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const std::uint32_t group = groupOf(items[i]);
        const bool grouped = group != kNoDrawGroup;
        if (!grouped || batchOfGroup[group] == kNoDrawGroup) {
            if (grouped)
                batchOfGroup[group] = static_cast<std::uint32_t>(result.batches.size());
            batchOfItem[i] = static_cast<std::uint32_t>(result.batches.size());
            result.batches.push_back({});
        } else {
            batchOfItem[i] = batchOfGroup[group];
        }
        ++result.batches[batchOfItem[i]].count;
    }
    std::uint32_t first = 0;
    for (InstanceBatches::Batch& batch : result.batches) {
        batch.first = first;
        first += batch.count;
    }
    std::vector<std::uint32_t> filled(result.batches.size(), 0);
    result.items.resize(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
        const std::uint32_t batch = batchOfItem[i];
        result.items[result.batches[batch].first + filled[batch]++] = items[i];
    }
    return result;
}

// Batches only runs of consecutive items of one group, keeping the order: for blended surfaces, drawn back to front.
template <typename GroupOf>
InstanceBatches batchRuns(std::span<const std::uint32_t> items, GroupOf groupOf)
{
    InstanceBatches result{{items.begin(), items.end()}, {}};
    for (std::uint32_t i = 0; i < items.size(); ++i) {
        const std::uint32_t group = groupOf(items[i]);
        if (i == 0 || group == kNoDrawGroup || groupOf(items[i - 1]) != group)
            result.batches.push_back({i, 0});
        ++result.batches.back().count;
    }
    return result;
}

} // namespace penumbra::shadows
