#include "penumbra/parity/HeatMap.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <vector>

namespace penumbra::parity {
namespace {

// t in [0, 1] along black -> red -> yellow -> white; any difference at all is at least dark red.
void heat(std::byte* texel, float t)
{
    t = t > 0.0f ? std::clamp(t, 0.1f, 1.0f) : 0.0f;
    const float channels[3] = {std::clamp(3.0f * t, 0.0f, 1.0f), std::clamp(3.0f * t - 1.0f, 0.0f, 1.0f),
                               std::clamp(3.0f * t - 2.0f, 0.0f, 1.0f)};
    for (int c = 0; c < 3; ++c)
        texel[c] = std::byte(std::lround(channels[c] * 255.0f));
    texel[3] = std::byte{255};
}

rhi::Image blank(std::uint32_t width, std::uint32_t height)
{
    return {width, height, rhi::Format::RGBA8, std::vector<std::byte>(std::size_t(width) * height * 4)};
}

} // namespace

rhi::Image differenceHeatMap(const rhi::Image& a, const rhi::Image& b, int fullScale)
{
    if (a.width != b.width || a.height != b.height || a.format != rhi::Format::RGBA8 || b.format != rhi::Format::RGBA8)
        throw rhi::Error(fmt::format("heat map: needs two RGBA8 pictures of one size, got {}x{} and {}x{}", a.width,
                                     a.height, b.width, b.height));
    rhi::Image map = blank(a.width, a.height);
    for (std::size_t p = 0; p < std::size_t(a.width) * a.height; ++p) {
        int delta = 0;
        for (std::size_t c = 0; c < 3; ++c)
            delta = std::max(delta, std::abs(int(a.bytes[p * 4 + c]) - int(b.bytes[p * 4 + c])));
        heat(&map.bytes[p * 4], float(delta) / float(fullScale));
    }
    return map;
}

rhi::Image differenceHeatMap(std::span<const float> a, std::span<const float> b, std::uint32_t width,
                             std::uint32_t height, float fullScale)
{
    if (a.size() != std::size_t(width) * height || b.size() != a.size())
        throw rhi::Error(fmt::format("heat map: {} and {} values for {}x{} texels", a.size(), b.size(), width, height));
    rhi::Image map = blank(width, height);
    for (std::size_t p = 0; p < a.size(); ++p)
        heat(&map.bytes[p * 4], std::abs(a[p] - b[p]) / fullScale);
    return map;
}

} // namespace penumbra::parity
