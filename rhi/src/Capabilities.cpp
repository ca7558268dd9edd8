#include "penumbra/rhi/Device.hpp"

#include <fmt/format.h>

namespace penumbra::rhi {

std::string sampleCountList(std::uint32_t sampleCounts)
{
    std::string text;
    for (std::uint32_t count = 1; count <= 8; count *= 2)
        if (sampleCounts & count)
            text += (text.empty() ? "" : ", ") + fmt::format("{}", count);
    return text.empty() ? "none" : text;
}

std::uint32_t Capabilities::sampleCounts(std::span<const Format> targets) const
{
    std::uint32_t counts = 1 | 2 | 4 | 8;
    for (Format f : targets)
        counts &= format(f).sampleCounts;
    return counts;
}

} // namespace penumbra::rhi
