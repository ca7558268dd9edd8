// rhi::generateMipChain's alpha-coverage preservation, on the CPU.
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/MipChain.hpp"

#include <gtest/gtest.h>

#include <cstdint>
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

} // namespace
} // namespace penumbra::rhi
