#include "TransientSlots.hpp"

#include <algorithm>
#include <map>
#include <numeric>

namespace penumbra::render {

std::vector<std::uint32_t> assignTransientSlots(const std::vector<TransientLifetime>& lifetimes)
{
    std::vector<std::size_t> order(lifetimes.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return lifetimes[a].firstPass < lifetimes[b].firstPass; });
    // Per kind, the last pass of each slot's current texture.
    std::map<std::size_t, std::vector<std::size_t>> slotsEnd;
    std::vector<std::uint32_t> slots(lifetimes.size(), 0);
    for (std::size_t i : order) {
        const TransientLifetime& life = lifetimes[i];
        std::vector<std::size_t>& ends = slotsEnd[life.kind];
        const auto free = std::find_if(ends.begin(), ends.end(), [&](std::size_t end) { return end < life.firstPass; });
        if (free == ends.end()) {
            slots[i] = static_cast<std::uint32_t>(ends.size());
            ends.push_back(life.lastPass);
        } else {
            slots[i] = static_cast<std::uint32_t>(free - ends.begin());
            *free = life.lastPass;
        }
    }
    return slots;
}

} // namespace penumbra::render
