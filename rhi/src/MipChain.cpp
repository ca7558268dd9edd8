#include "penumbra/rhi/MipChain.hpp"

#include "BoxPyramid.hpp"

#include "penumbra/rhi/BackendSupport.hpp"
#include "penumbra/rhi/ColorSpace.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/HugePages.hpp"

#include <algorithm>
#include <array>
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

// The linear value of each 8-bit code, unorm and sRGB-decoded: a lookup instead of a division and a pow per
// texel channel, computed by the same expressions, so the same doubles.
struct UnormTables {
    std::array<double, 256> linear{};
    std::array<double, 256> srgb{};
};

const UnormTables& unormTables()
{
    static const UnormTables tables = [] {
        UnormTables made;
        for (std::size_t code = 0; code < 256; ++code) {
            made.linear[code] = double(code) / 255.0;
            made.srgb[code] = srgbToLinear(made.linear[code]);
        }
        return made;
    }();
    return tables;
}

// Decodes row `y` of level 0 into `out` (width * channels linear values).
void decodeRow(const Layout& layout, std::span<const std::byte> bytes, std::uint32_t width, std::uint32_t y,
               double* out)
{
    const std::size_t count = std::size_t(width) * layout.channels;
    const std::size_t first = std::size_t(y) * count;
    if (layout.floats) {
        for (std::size_t i = 0; i < count; ++i) {
            float f;
            std::memcpy(&f, bytes.data() + (first + i) * 4, 4);
            out[i] = f;
        }
        return;
    }
    const UnormTables& tables = unormTables();
    const auto* codes = reinterpret_cast<const std::uint8_t*>(bytes.data()) + first;
    if (!layout.srgb) {
        for (std::size_t i = 0; i < count; ++i)
            out[i] = tables.linear[codes[i]];
        return;
    }
    for (std::size_t i = 0; i < count; i += 4) {
        out[i] = tables.srgb[codes[i]];
        out[i + 1] = tables.srgb[codes[i + 1]];
        out[i + 2] = tables.srgb[codes[i + 2]];
        out[i + 3] = tables.linear[codes[i + 3]];
    }
}

// std::lround(std::clamp(value, 0.0, 1.0) * 255.0) as a byte, without the call: below 256 a value's fraction,
// scaled - trunc(scaled), is exact, and lround rounds it up from one half.
std::byte unormByte(double value)
{
    const double scaled = std::clamp(value, 0.0, 1.0) * 255.0;
    const auto whole = std::uint32_t(scaled);
    return std::byte(std::uint8_t(whole + (scaled - whole >= 0.5 ? 1u : 0u)));
}

// A linear value (alpha, or any channel of a format without sRGB) in the format's bytes.
void encodeLinear(const Layout& layout, double value, std::byte* out)
{
    if (layout.floats) {
        const float f = float(value);
        std::memcpy(out, &f, 4);
    } else {
        *out = unormByte(value);
    }
}

// Encodes `count` values to `out` in the format's bytes; with `skipAlpha`, channel 3 is left for later.
void encodeValues(const Layout& layout, const double* values, std::size_t count, bool skipAlpha, std::byte* out)
{
    const std::size_t valueBytes = layout.floats ? 4 : 1;
    for (std::size_t i = 0; i < count; ++i) {
        const bool alpha = layout.channels == 4 && i % 4 == 3;
        if (layout.srgb && !alpha)
            out[i] = std::byte(linearToSrgbCode(values[i]));
        else if (!(alpha && skipAlpha))
            encodeLinear(layout, values[i], out + i * valueBytes);
    }
}

// Values of `values[stride - 1]`, `values[2 * stride - 1]`... (alphas) whose product with `scale` reaches `cutoff`.
std::size_t alphaCovered(const double* values, std::size_t count, std::size_t stride, double scale, double cutoff)
{
    std::size_t covered = 0;
    for (std::size_t i = stride - 1; i < count; i += stride)
        covered += values[i] * scale >= cutoff ? 1 : 0;
    return covered;
}

// The alpha scale that brings the share of `alphas` reaching `cutoff` as close to `coverage` as a bisection finds
// (coverage grows with the scale).
double alphaScaleFor(const std::vector<double>& alphas, double coverage, double cutoff)
{
    double low = 0.0, high = 64.0;
    for (int step = 0; step < 32; ++step) {
        const double mid = 0.5 * (low + high);
        (double(alphaCovered(alphas.data(), alphas.size(), 1, mid, cutoff)) / double(alphas.size()) < coverage ? low
                                                                                                               : high) =
            mid;
    }
    return high;
}

// The share of level 0's texels whose alpha reaches `cutoff`, decoded a row at a time.
double alphaCoverage(const Layout& layout, std::span<const std::byte> level0, std::uint32_t width, std::uint32_t height,
                     double cutoff)
{
    std::vector<double> decoded(std::size_t(width) * layout.channels);
    std::size_t covered = 0;
    for (std::uint32_t y = 0; y < height; ++y) {
        decodeRow(layout, level0, width, y, decoded.data());
        covered += alphaCovered(decoded.data(), decoded.size(), 4, 1.0, cutoff);
    }
    return double(covered) / double(std::size_t(width) * height);
}

void checkChain(const Layout& layout, Format format, std::uint32_t width, std::uint32_t height, std::uint32_t levels,
                std::span<const std::byte> level0, std::optional<float> alphaCutoff)
{
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
}

} // namespace

std::span<const std::byte> MipLevels::level(std::uint32_t level) const
{
    if (level == 0 || level >= levels())
        throw Error(fmt::format("MipLevels: level {} is outside 1..{}", level, levels() - 1));
    return {bytes_.get() + offsets_[level - 1], offsets_[level] - offsets_[level - 1]};
}

MipLevels generateMipLevels(Format format, std::uint32_t width, std::uint32_t height, std::uint32_t levels,
                            std::span<const std::byte> level0, std::optional<float> alphaCutoff)
{
    const Layout layout = layoutOf(format);
    checkChain(layout, format, width, height, levels, level0, alphaCutoff);
    MipLevels made;
    made.offsets_.push_back(0);
    for (std::uint32_t level = 1; level < levels; ++level)
        made.offsets_.push_back(made.offsets_.back() +
                                std::size_t(mipExtent(width, level)) * mipExtent(height, level) * texelSize(format));
    made.bytes_ = std::make_unique_for_overwrite<std::byte[]>(made.offsets_.back());
    adviseHugePages(made.bytes_.get(), made.offsets_.back()); // 5.3 MiB for a 2048 x 2048 RGBA8 texture
    // With a cutoff, each level's alpha is scaled once the whole level is known: its alphas wait here.
    std::vector<std::vector<double>> alphas(alphaCutoff ? levels : 0);
    for (std::uint32_t level = 1; level < alphas.size(); ++level)
        alphas[level].reserve(std::size_t(mipExtent(width, level)) * mipExtent(height, level));
    const std::size_t valueBytes = layout.floats ? 4 : 1;
    const auto rowDone = [&](std::uint32_t level, std::uint32_t y, const double* values) {
        const std::size_t count = std::size_t(mipExtent(width, level)) * layout.channels;
        encodeValues(layout, values, count, alphaCutoff.has_value(),
                     made.bytes_.get() + made.offsets_[level - 1] + y * count * valueBytes);
        for (std::size_t i = 3; alphaCutoff && i < count; i += 4)
            alphas[level].push_back(values[i]);
    };
    BoxPyramid(
        width, height, layout.channels, levels,
        [&](std::uint32_t y, double* out) { decodeRow(layout, level0, width, y, out); }, rowDone)
        .run();
    if (!alphaCutoff)
        return made;
    const double coverage = alphaCoverage(layout, level0, width, height, *alphaCutoff);
    for (std::uint32_t level = 1; level < levels; ++level) {
        const double scale = alphaScaleFor(alphas[level], coverage, *alphaCutoff);
        std::byte* out = made.bytes_.get() + made.offsets_[level - 1];
        for (std::size_t t = 0; t < alphas[level].size(); ++t)
            encodeLinear(layout, std::min(alphas[level][t] * scale, 1.0), out + (t * 4 + 3) * valueBytes);
    }
    return made;
}

std::vector<std::vector<std::byte>> generateMipChain(Format format, std::uint32_t width, std::uint32_t height,
                                                     std::uint32_t levels, std::span<const std::byte> level0,
                                                     std::optional<float> alphaCutoff)
{
    const MipLevels below = generateMipLevels(format, width, height, levels, level0, alphaCutoff);
    std::vector<std::vector<std::byte>> chain{std::vector<std::byte>(level0.begin(), level0.end())};
    for (std::uint32_t level = 1; level < levels; ++level)
        chain.emplace_back(below.level(level).begin(), below.level(level).end());
    return chain;
}

void writeMipChain(Device& device, Texture& texture, std::uint32_t layer, std::span<const std::byte> level0,
                   std::optional<float> alphaCutoff)
{
    const TextureDesc& desc = texture.desc();
    const MipLevels below =
        generateMipLevels(desc.format, desc.width, desc.height, desc.mipLevels, level0, alphaCutoff);
    device.writeTexture(texture, layer, 0, level0);
    for (std::uint32_t level = 1; level < desc.mipLevels; ++level)
        device.writeTexture(texture, layer, level, below.level(level));
}

} // namespace penumbra::rhi
