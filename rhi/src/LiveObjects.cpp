#include "penumbra/rhi/LiveObjects.hpp"

#include <atomic>

namespace penumbra::rhi {
namespace {

std::array<std::atomic<std::int64_t>, kObjectKindCount> live{};

} // namespace

std::string_view objectKindName(ObjectKind kind)
{
    static constexpr std::array<std::string_view, kObjectKindCount> names = {
        "device",   "buffer",      "texture",          "sampler",   "framebuffer", "shader",
        "pipeline", "commandList", "timestampQueries", "swapchain", "bindingSet"};
    return names.at(std::size_t(kind));
}

LiveObjectCounts liveObjectCounts()
{
    LiveObjectCounts counts{};
    for (std::size_t i = 0; i < kObjectKindCount; ++i)
        counts[i] = live[i].load(std::memory_order_relaxed);
    return counts;
}

namespace detail {

void countLiveObject(ObjectKind kind, int change) noexcept
{
    live[std::size_t(kind)].fetch_add(change, std::memory_order_relaxed);
}

} // namespace detail
} // namespace penumbra::rhi
