// rhi::generateMipChain's alpha-coverage preservation, its bytes against a plain reference, and the sRGB code table
// against its formula, on the CPU.
#include "penumbra/rhi/ColorSpace.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/MipChain.hpp"
#include "penumbra/rhi/Resources.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

namespace penumbra::rhi {
namespace {

// 8 x 8 grey texels, opaque in column 0 only: a one-texel stalk, an eighth of the texels.
std::vector<std::uint8_t> stalk()
{
    std::vector<std::uint8_t> rgba(8 * 8 * 4, 128);
    for (std::size_t texel = 0; texel < 64; ++texel)
        rgba[texel * 4 + 3] = texel % 8 == 0 ? 255 : 0;
    return rgba;
}

std::size_t texelsReaching(const std::vector<std::byte>& level, double cutoff)
{
    std::size_t count = 0;
    for (std::size_t i = 3; i < level.size(); i += 4)
        count += double(std::uint8_t(level[i])) / 255.0 >= cutoff ? 1 : 0;
    return count;
}

TEST(MipChainTest, AlphaCutoffKeepsAlphaTestedCoverageThatTheBoxFilterLoses)
{
    const std::vector<std::uint8_t> level0 = stalk();
    const auto bytes = std::as_bytes(std::span(level0));
    const auto plain = generateMipChain(Format::RGBA8, 8, 8, 3, bytes);
    const auto kept = generateMipChain(Format::RGBA8, 8, 8, 3, bytes, 0.6f);
    // Averaged with its empty neighbour the stalk's alpha halves, below a 0.6 cutoff: it vanishes.
    EXPECT_EQ(texelsReaching(plain[1], 0.6), 0u);
    // Scaled, the stalk stays: 4 of level 1's 16 texels, the fewest that cover at least level 0's eighth.
    EXPECT_EQ(texelsReaching(kept[1], 0.6), 4u);
    EXPECT_GE(texelsReaching(kept[2], 0.6), 1u);
    EXPECT_EQ(kept[0], plain[0]) << "level 0 is the texture as given";
    for (std::size_t i = 0; i < kept[1].size(); i += 4)
        EXPECT_EQ(kept[1][i], plain[1][i]) << "colour is not touched";
}

TEST(MipChainTest, AlphaCutoffNeedsAnRgbaFormatAndACutoffInRange)
{
    const std::vector<std::uint8_t> r8(64, 255);
    EXPECT_THROW(generateMipChain(Format::R8, 8, 8, 2, std::as_bytes(std::span(r8)), 0.5f), Error);
    const std::vector<std::uint8_t> rgba = stalk();
    EXPECT_THROW(generateMipChain(Format::RGBA8, 8, 8, 2, std::as_bytes(std::span(rgba)), 0.0f), Error);
    EXPECT_THROW(generateMipChain(Format::RGBA8, 8, 8, 2, std::as_bytes(std::span(rgba)), 1.5f), Error);
}

// The box filter as MipChain.hpp states it, written plainly: whole planes of doubles, each axis halved in a pass of
// its own (x first), every sum adding weight * value in ascending source order from 0.0. The fast path must give
// these bytes (the frame hashes pin them).
struct Plane {
    std::uint32_t width = 0, height = 0;
    std::vector<double> values;
};

Plane halvedPlane(const Plane& source, std::uint32_t channels, bool alongX)
{
    const std::uint32_t from = alongX ? source.width : source.height;
    const std::uint32_t to = std::max(from / 2, 1u);
    Plane out{alongX ? to : source.width, alongX ? source.height : to, {}};
    out.values.assign(std::size_t(out.width) * out.height * channels, 0.0);
    const double scale = double(from) / double(to);
    for (std::uint32_t d = 0; d < to; ++d) {
        const double begin = d * scale, end = (d + 1) * scale;
        for (auto s = std::uint32_t(begin); s < from && s < end; ++s) {
            const double weight = (std::min(end, s + 1.0) - std::max(begin, double(s))) / scale;
            for (std::uint32_t r = 0; r < (alongX ? source.height : source.width); ++r) {
                const std::size_t src = alongX ? std::size_t(r) * source.width + s : std::size_t(s) * source.width + r;
                const std::size_t dst = alongX ? std::size_t(r) * out.width + d : std::size_t(d) * out.width + r;
                for (std::uint32_t c = 0; c < channels; ++c)
                    out.values[dst * channels + c] += weight * source.values[src * channels + c];
            }
        }
    }
    return out;
}

double coverageOf(const std::vector<double>& values, double scale, double cutoff)
{
    std::size_t covered = 0;
    for (std::size_t i = 3; i < values.size(); i += 4)
        covered += values[i] * scale >= cutoff ? 1 : 0;
    return double(covered) / double(values.size() / 4);
}

std::vector<std::vector<std::byte>> referenceChain(std::uint32_t channels, bool floats, bool srgb, std::uint32_t width,
                                                   std::uint32_t height, const std::vector<std::byte>& level0,
                                                   std::optional<float> cutoff)
{
    Plane plane{width, height, std::vector<double>(std::size_t(width) * height * channels)};
    for (std::size_t i = 0; i < plane.values.size(); ++i) {
        float f = 0.0f;
        if (floats)
            std::memcpy(&f, level0.data() + i * 4, 4);
        const double unorm = floats ? 0.0 : double(std::uint8_t(level0[i])) / 255.0;
        plane.values[i] = floats ? double(f) : srgb && i % 4 != 3 ? srgbToLinear(unorm) : unorm;
    }
    const double coverage = cutoff ? coverageOf(plane.values, 1.0, *cutoff) : 0.0;
    std::vector<std::vector<std::byte>> chain{level0};
    for (std::uint32_t level = 1; level < fullMipChain(width, height); ++level) {
        if (plane.width > 1)
            plane = halvedPlane(plane, channels, true);
        if (plane.height > 1)
            plane = halvedPlane(plane, channels, false);
        std::vector<double> values = plane.values;
        if (cutoff) {
            double low = 0.0, high = 64.0;
            for (int step = 0; step < 32; ++step) {
                const double mid = 0.5 * (low + high);
                (coverageOf(values, mid, *cutoff) < coverage ? low : high) = mid;
            }
            for (std::size_t i = 3; i < values.size(); i += 4)
                values[i] = std::min(values[i] * high, 1.0);
        }
        std::vector<std::byte> bytes(values.size() * (floats ? 4 : 1));
        for (std::size_t i = 0; i < values.size(); ++i) {
            const float f = float(values[i]);
            const double unorm = srgb && i % 4 != 3 ? linearToSrgb(std::clamp(values[i], 0.0, 1.0)) : values[i];
            if (floats)
                std::memcpy(bytes.data() + i * 4, &f, 4);
            else
                bytes[i] = std::byte(std::uint8_t(std::lround(std::clamp(unorm, 0.0, 1.0) * 255.0)));
        }
        chain.push_back(bytes);
    }
    return chain;
}

TEST(MipChainTest, EveryFormatGivesTheReferenceBytesOnOddAndEvenSizes)
{
    struct Case {
        Format format;
        std::uint32_t channels;
        bool floats, srgb;
    };
    const Case cases[] = {{Format::RGBA8, 4, false, false}, {Format::RGBA8_SRGB, 4, false, true},
                          {Format::R8, 1, false, false},    {Format::RG8, 2, false, false},
                          {Format::R32F, 1, true, false},   {Format::RGBA32F, 4, true, false}};
    const std::uint32_t sizes[][2] = {{37, 23}, {1, 9}, {9, 1}, {3, 3}, {16, 8}, {5, 2}, {2, 13}};
    std::mt19937 random(45);
    for (const Case& c : cases) {
        for (const auto& size : sizes) {
            const std::size_t texels = std::size_t(size[0]) * size[1];
            std::vector<std::byte> level0(texels * c.channels * (c.floats ? 4 : 1));
            for (std::size_t i = 0; i < level0.size(); i += c.floats ? 4 : 1) {
                // Floats include negatives, -0.0 and values over 1, which the 8-bit formats cannot hold.
                const float f = i % 28 == 0 ? -0.0f : std::uniform_real_distribution<float>(-0.5f, 2.0f)(random);
                if (c.floats)
                    std::memcpy(level0.data() + i, &f, 4);
                else
                    level0[i] = std::byte(random());
            }
            for (const std::optional<float> cutoff : {std::optional<float>(), std::optional(0.5f)}) {
                if (cutoff && c.channels != 4)
                    continue;
                const auto chain =
                    generateMipChain(c.format, size[0], size[1], fullMipChain(size[0], size[1]), level0, cutoff);
                EXPECT_EQ(chain, referenceChain(c.channels, c.floats, c.srgb, size[0], size[1], level0, cutoff))
                    << formatName(c.format) << " " << size[0] << "x" << size[1] << (cutoff ? " with a cutoff" : "");
            }
        }
    }
}

// generateMipLevels holds what generateMipChain returns below level 0, in one allocation.
TEST(MipChainTest, MipLevelsAreTheChainBelowLevelZero)
{
    const std::vector<std::uint8_t> level0 = stalk();
    const auto bytes = std::as_bytes(std::span(level0));
    const auto chain = generateMipChain(Format::RGBA8_SRGB, 8, 8, 4, bytes, 0.5f);
    const MipLevels below = generateMipLevels(Format::RGBA8_SRGB, 8, 8, 4, bytes, 0.5f);
    ASSERT_EQ(below.levels(), 4u);
    for (std::uint32_t level = 1; level < 4; ++level)
        EXPECT_TRUE(std::ranges::equal(below.level(level), chain[level])) << "level " << level;
    EXPECT_THROW(below.level(0), Error);
}

// linearToSrgbCode's table gives the formula's code: beside every value where the code steps up (where the sRGB
// curve crosses a half code), beside the table's guard bands around them, and at random values.
TEST(MipChainTest, SrgbCodesAreTheFormulas)
{
    const auto formula = [](double linear) {
        return std::uint8_t(std::lround(std::clamp(linearToSrgb(std::clamp(linear, 0.0, 1.0)), 0.0, 1.0) * 255.0));
    };
    std::vector<double> values{-1.0, -0.0, 0.0, 1e-300, 1.0, 2.0, std::nextafter(1.0, 0.0), 0.5};
    for (int code = 1; code < 256; ++code) {
        const double step = srgbToLinear((code - 0.5) / 255.0);
        for (const double near : {step, step * (1.0 - 1e-9), step * (1.0 + 1e-9)}) {
            double below = near, above = near;
            for (int ulp = 0; ulp < 100; ++ulp) {
                values.push_back(below = std::nextafter(below, 0.0));
                values.push_back(above = std::nextafter(above, 1.0));
            }
        }
    }
    std::mt19937_64 random(45);
    for (int i = 0; i < 50000; ++i)
        values.push_back(std::uniform_real_distribution<double>(0.0, 1.0)(random));
    std::size_t wrong = 0;
    for (const double value : values)
        wrong += linearToSrgbCode(value) != formula(value) ? 1 : 0;
    EXPECT_EQ(wrong, 0u) << "of " << values.size() << " values";
}

} // namespace
} // namespace penumbra::rhi
