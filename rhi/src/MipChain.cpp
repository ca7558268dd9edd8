#include "penumbra/rhi/MipChain.hpp"

#include "penumbra/rhi/BackendSupport.hpp"
#include "penumbra/rhi/ColorSpace.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fmt/format.h>

namespace penumbra::rhi {
namespace {

// How a format's texels become the values the box filter averages, and back.
struct Layout {
    std::uint32_t channels = 0;
    bool floats = false; // 32-bit floats, else 8-bit unsigned normalised
    bool srgb = false; // colour channels sRGB-encoded, alpha (channel 3) linear
};

Layout layoutOf(Format format)
{
    switch (format) {
    case Format::RGBA8:
        return {4, false, false};
    case Format::RGBA8_SRGB:
        return {4, false, true};
    case Format::R8:
        return {1, false, false};
    case Format::RG8:
        return {2, false, false};
    case Format::R32F:
        return {1, true, false};
    case Format::RGBA32F:
        return {4, true, false};
    default:
        break;
    }
    throw Error(fmt::format("generateMipChain: {} is not one of RGBA8, RGBA8_SRGB, R8, RG8, R32F, RGBA32F",
                            formatName(format)));
}

struct Plane {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<double> values; // width * height * channels, linear light
};

Plane decode(const Layout& layout, std::uint32_t width, std::uint32_t height, std::span<const std::byte> bytes)
{
    Plane plane{width, height, std::vector<double>(std::size_t(width) * height * layout.channels)};
    for (std::size_t i = 0; i < plane.values.size(); ++i) {
        if (layout.floats) {
            float f;
            std::memcpy(&f, bytes.data() + i * 4, 4);
            plane.values[i] = f;
            continue;
        }
        const double unorm = double(std::uint8_t(bytes[i])) / 255.0;
        plane.values[i] = layout.srgb && i % 4 != 3 ? srgbToLinear(unorm) : unorm;
    }
    return plane;
}

std::vector<std::byte> encode(const Layout& layout, const Plane& plane)
{
    std::vector<std::byte> bytes(plane.values.size() * (layout.floats ? 4 : 1));
    for (std::size_t i = 0; i < plane.values.size(); ++i) {
        const double v = plane.values[i];
        if (layout.floats) {
            const float f = float(v);
            std::memcpy(bytes.data() + i * 4, &f, 4);
            continue;
        }
        const double unorm = layout.srgb && i % 4 != 3 ? linearToSrgb(std::clamp(v, 0.0, 1.0)) : v;
        bytes[i] = std::byte(std::uint8_t(std::lround(std::clamp(unorm, 0.0, 1.0) * 255.0)));
    }
    return bytes;
}

// Halves one axis of `source` with the box filter; `alongX` picks the axis, the other keeps its size.
Plane halve(const Plane& source, std::uint32_t channels, bool alongX)
{
    const std::uint32_t from = alongX ? source.width : source.height;
    const std::uint32_t to = std::max(from / 2, 1u);
    Plane out{alongX ? to : source.width, alongX ? source.height : to, {}};
    out.values.assign(std::size_t(out.width) * out.height * channels, 0.0);
    const double scale = double(from) / double(to); // source texels per destination texel
    for (std::uint32_t d = 0; d < to; ++d) {
        const double begin = d * scale, end = (d + 1) * scale;
        for (auto s = std::uint32_t(begin); s < from && s < end; ++s) {
            const double weight = (std::min(end, s + 1.0) - std::max(begin, double(s))) / scale;
            const std::uint32_t rows = alongX ? source.height : source.width;
            for (std::uint32_t r = 0; r < rows; ++r) {
                const std::size_t src = alongX ? std::size_t(r) * source.width + s : std::size_t(s) * source.width + r;
                const std::size_t dst = alongX ? std::size_t(r) * out.width + d : std::size_t(d) * out.width + r;
                for (std::uint32_t c = 0; c < channels; ++c)
                    out.values[dst * channels + c] += weight * source.values[src * channels + c];
            }
        }
    }
    return out;
}

// Share of the plane's texels whose alpha (channel 3 of 4) times `scale` reaches `cutoff`.
double alphaCoverage(const Plane& plane, double scale, double cutoff)
{
    std::size_t covered = 0;
    for (std::size_t i = 3; i < plane.values.size(); i += 4)
        covered += plane.values[i] * scale >= cutoff ? 1 : 0;
    return double(covered) / double(plane.values.size() / 4);
}

// `plane` with its alpha scaled so that alphaCoverage is as close to `coverage` as a bisection of the scale finds
// (coverage grows with the scale), clamped to [0, 1].
Plane withAlphaCoverage(Plane plane, double coverage, double cutoff)
{
    double low = 0.0, high = 64.0;
    for (int step = 0; step < 32; ++step) {
        const double mid = 0.5 * (low + high);
        (alphaCoverage(plane, mid, cutoff) < coverage ? low : high) = mid;
    }
    for (std::size_t i = 3; i < plane.values.size(); i += 4)
        plane.values[i] = std::min(plane.values[i] * high, 1.0);
    return plane;
}

} // namespace

std::vector<std::vector<std::byte>> generateMipChain(Format format, std::uint32_t width, std::uint32_t height,
                                                     std::uint32_t levels, std::span<const std::byte> level0,
                                                     std::optional<float> alphaCutoff)
{
    const Layout layout = layoutOf(format);
    const std::uint64_t expected = std::uint64_t(width) * height * texelSize(format);
    if (width == 0 || height == 0 || level0.size() != expected)
        throw Error(fmt::format("generateMipChain: level 0 of {}x{} {} takes {} bytes, got {}", width, height,
                                formatName(format), expected, level0.size()));
    if (levels == 0 || levels > fullMipChain(width, height))
        throw Error(fmt::format("generateMipChain: {} levels is outside 1..{} for {}x{}", levels,
                                fullMipChain(width, height), width, height));
    if (alphaCutoff && (layout.channels != 4 || !(*alphaCutoff > 0.0f && *alphaCutoff <= 1.0f)))
        throw Error(fmt::format("generateMipChain: an alpha cutoff ({}) needs an RGBA format and a value in (0, 1], "
                                "got {}",
                                *alphaCutoff, formatName(format)));
    std::vector<std::vector<std::byte>> chain{std::vector<std::byte>(level0.begin(), level0.end())};
    Plane plane = decode(layout, width, height, level0);
    const double coverage = alphaCutoff ? alphaCoverage(plane, 1.0, *alphaCutoff) : 0.0;
    for (std::uint32_t level = 1; level < levels; ++level) {
        if (plane.width > 1)
            plane = halve(plane, layout.channels, true);
        if (plane.height > 1)
            plane = halve(plane, layout.channels, false);
        chain.push_back(encode(layout, alphaCutoff ? withAlphaCoverage(plane, coverage, *alphaCutoff) : plane));
    }
    return chain;
}

void writeMipChain(Device& device, Texture& texture, std::uint32_t layer, std::span<const std::byte> level0,
                   std::optional<float> alphaCutoff)
{
    const TextureDesc& desc = texture.desc();
    const auto chain = generateMipChain(desc.format, desc.width, desc.height, desc.mipLevels, level0, alphaCutoff);
    for (std::uint32_t level = 0; level < desc.mipLevels; ++level)
        device.writeTexture(texture, layer, level, chain[level]);
}

} // namespace penumbra::rhi
