#include "penumbra/rhi/MipChain.hpp"

#include "penumbra/rhi/BackendSupport.hpp"
#include "penumbra/rhi/ColorSpace.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <memory>

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

std::vector<std::byte> encode(const Layout& layout, std::span<const double> values, std::optional<double> alphaScale)
{
    std::vector<std::byte> bytes(values.size() * (layout.floats ? 4 : 1));
    for (std::size_t i = 0; i < values.size(); ++i) {
        const bool alpha = i % 4 == 3;
        const double v = alphaScale && alpha ? std::min(values[i] * *alphaScale, 1.0) : values[i];
        if (layout.floats) {
            const float f = float(v);
            std::memcpy(bytes.data() + i * 4, &f, 4);
            continue;
        }
        const double unorm = layout.srgb && !alpha ? linearToSrgb(std::clamp(v, 0.0, 1.0)) : v;
        bytes[i] = std::byte(std::uint8_t(std::lround(std::clamp(unorm, 0.0, 1.0) * 255.0)));
    }
    return bytes;
}

// The box filter along one axis halved from `from` texels: destination texel d averages sources
// [first[d], first[d + 1]) of `taps`, weighted by the share of its area each covers, in ascending source order.
struct AxisFilter {
    struct Tap {
        std::uint32_t source = 0;
        double weight = 0.0;
    };
    std::uint32_t to = 0;
    std::vector<std::size_t> first;
    std::vector<Tap> taps;
};

AxisFilter axisFilter(std::uint32_t from)
{
    AxisFilter filter;
    filter.to = std::max(from / 2, 1u);
    const double scale = double(from) / double(filter.to); // source texels per destination texel
    for (std::uint32_t d = 0; d < filter.to; ++d) {
        filter.first.push_back(filter.taps.size());
        const double begin = d * scale, end = (d + 1) * scale;
        for (auto s = std::uint32_t(begin); s < from && s < end; ++s)
            filter.taps.push_back({s, (std::min(end, s + 1.0) - std::max(begin, double(s))) / scale});
    }
    filter.first.push_back(filter.taps.size());
    return filter;
}

// One level filtered from the level above: both axes halved (an axis of one texel stays), the x axis first.
// Each sum starts at 0.0 and adds weight * value in ascending source order, the x sums before the y sums, so every
// level has the bits that filtering whole planes axis by axis gave. `sourceRow(y)` gives row y of the level above
// (width * channels values) and stays valid until the next call.
template <typename SourceRow>
void filterLevel(std::uint32_t width, std::uint32_t height, std::uint32_t channels, SourceRow&& sourceRow,
                 double* xScratch, double* out)
{
    const bool alongX = width > 1, alongY = height > 1;
    const AxisFilter xFilter = alongX ? axisFilter(width) : AxisFilter{};
    const std::uint32_t outWidth = alongX ? xFilter.to : width;
    const std::size_t rowValues = std::size_t(outWidth) * channels;
    // Row y of the level above halved along x: written to xScratch, or the row itself where x stays.
    const auto xRow = [&](std::uint32_t y, double* scratch) -> const double* {
        const double* source = sourceRow(y);
        if (!alongX)
            return source;
        for (std::uint32_t d = 0; d < xFilter.to; ++d) {
            for (std::uint32_t c = 0; c < channels; ++c) {
                double sum = 0.0;
                for (std::size_t t = xFilter.first[d]; t < xFilter.first[d + 1]; ++t)
                    sum += xFilter.taps[t].weight * source[std::size_t(xFilter.taps[t].source) * channels + c];
                scratch[std::size_t(d) * channels + c] = sum;
            }
        }
        return scratch;
    };
    if (!alongY) {
        if (const double* row = xRow(0, out); row != out)
            std::copy(row, row + rowValues, out);
        return;
    }
    const AxisFilter yFilter = axisFilter(height);
    for (std::uint32_t d = 0; d < yFilter.to; ++d) {
        double* target = out + std::size_t(d) * rowValues;
        for (std::size_t t = yFilter.first[d]; t < yFilter.first[d + 1]; ++t) {
            const double weight = yFilter.taps[t].weight;
            const double* row = xRow(yFilter.taps[t].source, xScratch);
            // The first tap adds to 0.0 as a zeroed sum would (0.0 + -0.0 is 0.0), without a pass to zero the row.
            for (std::size_t i = 0; i < rowValues; ++i)
                target[i] = (t == yFilter.first[d] ? 0.0 : target[i]) + weight * row[i];
        }
    }
}

// Texels of `values` (RGBA) whose alpha times `scale` reaches `cutoff`.
std::size_t alphaCovered(std::span<const double> values, double scale, double cutoff)
{
    std::size_t covered = 0;
    for (std::size_t i = 3; i < values.size(); i += 4)
        covered += values[i] * scale >= cutoff ? 1 : 0;
    return covered;
}

// The alpha scale that brings the share of `values`' texels reaching `cutoff` as close to `coverage` as a
// bisection finds (coverage grows with the scale).
double alphaScaleFor(std::span<const double> values, double coverage, double cutoff)
{
    double low = 0.0, high = 64.0;
    for (int step = 0; step < 32; ++step) {
        const double mid = 0.5 * (low + high);
        (double(alphaCovered(values, mid, cutoff)) / double(values.size() / 4) < coverage ? low : high) = mid;
    }
    return high;
}

std::size_t valuesOf(std::uint32_t width, std::uint32_t height, std::uint32_t channels)
{
    return std::size_t(width) * height * channels;
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
    if (levels == 1)
        return chain;
    const std::uint32_t channels = layout.channels;
    // Level 0 is decoded a row at a time, never whole; the levels below live in two buffers used in turn (odd
    // levels in the first, even in the second), allocated once and not zero-filled: a fresh zero-filled plane per
    // level was most of the time (docs/notes/2026-12-06-large-texture-loading.md).
    std::vector<double> decoded(std::size_t(width) * channels);
    std::vector<double> xScratch(std::size_t(std::max(width / 2, 1u)) * channels);
    const auto halvedSize = [](std::uint32_t size) { return std::max(size / 2, 1u); }; // an axis of the next level
    std::array<std::unique_ptr<double[]>, 2> planes;
    planes[0].reset(new double[valuesOf(halvedSize(width), halvedSize(height), channels)]);
    if (levels > 2)
        planes[1].reset(new double[valuesOf(halvedSize(halvedSize(width)), halvedSize(halvedSize(height)), channels)]);
    double coverage = 0.0;
    if (alphaCutoff) {
        std::size_t covered = 0;
        for (std::uint32_t y = 0; y < height; ++y) {
            decodeRow(layout, level0, width, y, decoded.data());
            covered += alphaCovered(decoded, 1.0, *alphaCutoff);
        }
        coverage = double(covered) / double(std::size_t(width) * height);
    }
    std::uint32_t w = width, h = height;
    const double* above = nullptr; // the level above, null for level 0 (read from its bytes)
    for (std::uint32_t level = 1; level < levels; ++level) {
        double* out = planes[(level - 1) % 2].get();
        const auto sourceRow = [&](std::uint32_t y) -> const double* {
            if (above)
                return above + std::size_t(y) * w * channels;
            decodeRow(layout, level0, width, y, decoded.data());
            return decoded.data();
        };
        filterLevel(w, h, channels, sourceRow, xScratch.data(), out);
        w = halvedSize(w);
        h = halvedSize(h);
        const std::span<const double> values(out, valuesOf(w, h, channels));
        chain.push_back(
            encode(layout, values,
                   alphaCutoff ? std::optional(alphaScaleFor(values, coverage, *alphaCutoff)) : std::nullopt));
        above = out;
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
