// Mip levels, the new formats, sRGB decoding and samplers (filters, LOD clamps, wrap modes, anisotropy), in
// every configuration through the real drivers.
#include "GpuTesting.hpp"
#include "TextureProbe.hpp"

#include "penumbra/rhi/ColorSpace.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/MipChain.hpp"

#include <array>
#include <fmt/format.h>

namespace penumbra::testing {
namespace {

using TextureTest = GpuTest;

constexpr std::array colorFormats{rhi::Format::RGBA8, rhi::Format::RGBA8_SRGB, rhi::Format::R8,
                                  rhi::Format::RG8,   rhi::Format::R16F,       rhi::Format::RG16F,
                                  rhi::Format::R32F,  rhi::Format::RGBA16F,    rhi::Format::RGBA32F};

// Bytes that differ per texel and level and are finite numbers in every format (float formats get small
// positive values, so no NaN payload can be rewritten on the way).
std::vector<std::byte> levelBytes(rhi::Format format, std::uint32_t texels, std::uint32_t level)
{
    std::vector<std::byte> bytes(std::size_t(texels) * rhi::texelSize(format));
    const bool halfs = format == rhi::Format::R16F || format == rhi::Format::RG16F || format == rhi::Format::RGBA16F;
    const bool floats = format == rhi::Format::R32F || format == rhi::Format::RGBA32F;
    for (std::size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = std::byte(std::uint8_t(i * 13 + level * 71 + 5));
    if (halfs)
        for (std::size_t i = 0; i + 1 < bytes.size(); i += 2) // exponent bits 0x3C: values in [1, 2)
            bytes[i + 1] = std::byte(0x3C | (std::uint8_t(bytes[i + 1]) & 0x03));
    if (floats)
        for (std::size_t i = 0; i + 3 < bytes.size(); i += 4) // exponent of 1.0: values in [1, 2)
            bytes[i + 3] = std::byte(0x3F);
    return bytes;
}

TEST_F(TextureTest, EveryMipLevelOfEveryFormatUploadsAndReadsBack)
{
    for (rhi::Format format : colorFormats) {
        // 5 x 3: odd sizes, levels 5x3, 2x1, 1x1.
        auto texture = device->createTexture({.width = 5,
                                              .height = 3,
                                              .layers = 2,
                                              .mipLevels = 3,
                                              .format = format,
                                              .debugName = std::string(rhi::formatName(format))});
        for (std::uint32_t layer = 0; layer < 2; ++layer)
            for (std::uint32_t level = 0; level < 3; ++level)
                device->writeTexture(*texture, layer, level,
                                     levelBytes(format, rhi::mipExtent(5, level) * rhi::mipExtent(3, level),
                                                level + 3 * layer));
        for (std::uint32_t layer = 0; layer < 2; ++layer) {
            for (std::uint32_t level = 0; level < 3; ++level) {
                const rhi::Image read = rhi::readTexture(*device, *texture, layer, level);
                EXPECT_EQ(read.width, rhi::mipExtent(5, level));
                EXPECT_EQ(read.height, rhi::mipExtent(3, level));
                EXPECT_EQ(read.bytes, levelBytes(format, read.width * read.height, level + 3 * layer))
                    << rhi::formatName(format) << " layer " << layer << " level " << level;
            }
        }
    }
}

TEST_F(TextureTest, CopyTextureCopiesEveryLevel)
{
    const rhi::TextureDesc desc{.width = 8, .height = 4, .mipLevels = rhi::fullMipChain(8, 4)};
    ASSERT_EQ(desc.mipLevels, 4u);
    auto source = device->createTexture(desc);
    auto destination = device->createTexture(desc);
    for (std::uint32_t level = 0; level < desc.mipLevels; ++level)
        device->writeTexture(*source, 0, level,
                             levelBytes(desc.format, rhi::mipExtent(8, level) * rhi::mipExtent(4, level), level));
    auto commands = device->createCommandList();
    commands->copyTexture(*source, 0, *destination, 0);
    device->submit(*commands);
    for (std::uint32_t level = 0; level < desc.mipLevels; ++level)
        EXPECT_EQ(rhi::readTexture(*device, *destination, 0, level).bytes,
                  rhi::readTexture(*device, *source, 0, level).bytes)
            << "level " << level;
}

// What Capabilities::formats says decides what creation does: a reported format works, with validation on.
TEST_F(TextureTest, ReportedFormatSupportHolds)
{
    const rhi::Capabilities& caps = device->capabilities();
    for (rhi::Format format : colorFormats) {
        const rhi::FormatSupport& support = caps.format(format);
        const rhi::TextureDesc desc{.width = 4,
                                    .height = 4,
                                    .format = format,
                                    .usage = rhi::TextureUsage::Sampled | rhi::TextureUsage::RenderTarget};
        if (support.sampled && support.renderTarget)
            EXPECT_NO_THROW(device->createTexture(desc)) << rhi::formatName(format);
        else
            EXPECT_THROW(device->createTexture(desc), rhi::UnsupportedError) << rhi::formatName(format);
    }
    // Both Mesa drivers sample, filter and render to every colour format of the RHI.
    for (rhi::Format format : colorFormats) {
        EXPECT_TRUE(caps.format(format).sampled) << rhi::formatName(format);
        EXPECT_TRUE(caps.format(format).linearFilter) << rhi::formatName(format);
        EXPECT_TRUE(caps.format(format).renderTarget) << rhi::formatName(format);
    }
}

// A render target of each new format keeps its clear value: exact in the unorm and float formats, the sRGB
// encoding of it in RGBA8_SRGB.
TEST_F(TextureTest, NewFormatsKeepTheClearValue)
{
    const glm::vec4 value(0.2f, 0.6f, 0.4f, 0.8f); // 51, 153, 102, 204 in unorm8
    TextureProbe probe(*device);
    auto sampler = device->createSampler({.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest});
    for (rhi::Format format : {rhi::Format::R8, rhi::Format::RG8, rhi::Format::R16F, rhi::Format::RG16F,
                               rhi::Format::R32F, rhi::Format::RGBA8_SRGB}) {
        auto texture = device->createTexture({.width = 4,
                                              .height = 4,
                                              .format = format,
                                              .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled});
        const rhi::Attachment attachment{texture.get(), 0};
        auto framebuffer = device->createFramebuffer({.colors = {&attachment, 1}});
        auto commands = device->createCommandList();
        commands->beginPass({.framebuffer = framebuffer.get(), .clearColor = value});
        commands->endPass();
        device->submit(*commands);
        // Sampled back through a nearest sampler: the decoded value in linear terms, whatever the storage.
        const glm::vec4 read = probe.sample(*texture, *sampler, {.origin = {0.5f, 0.5f}}).front();
        const int channels = format == rhi::Format::R8 || format == rhi::Format::R16F || format == rhi::Format::R32F
                                 ? 1
                                 : (format == rhi::Format::RGBA8_SRGB ? 4 : 2);
        if (format != rhi::Format::RGBA8_SRGB) {
            for (int c = 0; c < 4; ++c)
                EXPECT_NEAR(read[c], c < channels ? value[c] : (c == 3 ? 1.0f : 0.0f), 1e-3f)
                    << rhi::formatName(format) << " channel " << c;
            continue;
        }
        // Stored encoded (within a step of the exact encoding; alpha linear), sampled decoded.
        const rhi::Image raw = rhi::readTexture(*device, *texture);
        for (int c = 0; c < 4; ++c) {
            const double stored = double(std::uint8_t(raw.texel(1, 1)[c])) / 255.0;
            const double exact = c == 3 ? value[c] : rhi::linearToSrgb(value[c]);
            EXPECT_NEAR(stored, exact, 1.0 / 255.0) << "channel " << c;
            EXPECT_NEAR(read[c], c == 3 ? stored : rhi::srgbToLinear(stored), 2e-3) << "channel " << c;
        }
    }
}

// RGBA8_SRGB texels reach the shader decoded to linear light, and filtering happens after decoding.
TEST_F(TextureTest, SrgbTexelsAreDecodedBeforeFiltering)
{
    const std::vector<std::uint8_t> texels = {0, 64, 128, 128, 255, 255, 255, 255};
    auto srgb = device->createTexture({.width = 2, .height = 1, .format = rhi::Format::RGBA8_SRGB});
    auto plain = device->createTexture({.width = 2, .height = 1, .format = rhi::Format::RGBA8});
    device->writeTexture(*srgb, 0, 0, std::as_bytes(std::span(texels)));
    device->writeTexture(*plain, 0, 0, std::as_bytes(std::span(texels)));
    auto nearest = device->createSampler({.magFilter = rhi::Filter::Nearest, .minFilter = rhi::Filter::Nearest});
    auto linear = device->createSampler({});
    TextureProbe probe(*device);

    const glm::vec4 decoded = probe.sample(*srgb, *nearest, {.origin = {0.25f, 0.5f}}).front();
    const glm::vec4 raw = probe.sample(*plain, *nearest, {.origin = {0.25f, 0.5f}}).front();
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(decoded[c], rhi::srgbToLinear(texels[c] / 255.0), 2e-3) << "channel " << c;
        EXPECT_NEAR(raw[c], texels[c] / 255.0f, 1e-3f) << "channel " << c;
    }
    EXPECT_NEAR(decoded.a, 128.0f / 255.0f, 1e-3f) << "alpha is linear";
    EXPECT_GT(std::abs(decoded.g - raw.g), 0.1f) << "the sRGB format must decode";

    // Half way between black and white: 0.5 in linear light (decode, then filter), not the decoded 0.5 of
    // filtering the encoded values (0.214).
    const glm::vec4 between = probe.sample(*srgb, *linear, {.origin = {0.5f, 0.5f}}).front();
    EXPECT_NEAR(between.r, 0.5f, 4e-3f) << "red: 0 and 255";
}

// A chain whose level L is one solid colour, (L + 1) / 8 in red: which levels a sample blends is read off it.
std::unique_ptr<rhi::Texture> levelCodedTexture(rhi::Device& device, std::uint32_t size)
{
    const std::uint32_t levels = rhi::fullMipChain(size, size);
    auto texture =
        device.createTexture({.width = size, .height = size, .mipLevels = levels, .format = rhi::Format::R32F});
    for (std::uint32_t level = 0; level < levels; ++level) {
        const std::uint32_t extent = rhi::mipExtent(size, level);
        const std::vector<float> values(std::size_t(extent) * extent, float(level + 1) / 8.0f);
        device.writeTexture(*texture, 0, level, std::as_bytes(std::span(values)));
    }
    return texture;
}

float levelOf(float red) { return red * 8.0f - 1.0f; }

TEST_F(TextureTest, MipFiltersAndLodClampsPickTheLevels)
{
    auto texture = levelCodedTexture(*device, 64); // levels 0..6
    TextureProbe probe(*device);
    auto level = [&](const rhi::SamplerDesc& desc, float lod) {
        auto sampler = device->createSampler(desc);
        return levelOf(probe.sample(*texture, *sampler, {.origin = {0.5f, 0.5f}, .lod = lod}).front().r);
    };
    const rhi::SamplerDesc nearest{.mipFilter = rhi::MipFilter::Nearest};
    const rhi::SamplerDesc trilinear{.mipFilter = rhi::MipFilter::Linear};
    EXPECT_NEAR(level(nearest, 2.0f), 2.0f, 1e-4f);
    EXPECT_NEAR(level(nearest, 4.2f), 4.0f, 1e-4f);
    EXPECT_NEAR(level(trilinear, 2.25f), 2.25f, 1.0f / 256.0f) << "blends levels 2 and 3";
    EXPECT_NEAR(level({.mipFilter = rhi::MipFilter::None}, 4.0f), 0.0f, 1e-4f) << "None reads level 0 only";
    EXPECT_NEAR(level({.mipFilter = rhi::MipFilter::Nearest, .minLod = 3.0f}, 0.0f), 3.0f, 1e-4f) << "minLod";
    EXPECT_NEAR(level({.mipFilter = rhi::MipFilter::Nearest, .maxLod = 1.0f}, 5.0f), 1.0f, 1e-4f) << "maxLod";
    EXPECT_NEAR(level({.mipFilter = rhi::MipFilter::Linear, .minLod = 1.5f, .maxLod = 1.5f}, 6.0f), 1.5f, 1.0f / 256.0f)
        << "both clamps";
}

// Four texels across u (and down v), sampled three eighths of the texture past either edge.
TEST_F(TextureTest, WrapModesAddressTexelsOutsideTheTexture)
{
    auto texture = device->createTexture({.width = 4, .height = 4, .format = rhi::Format::RG8});
    std::vector<std::uint8_t> texels;
    for (std::uint8_t y = 0; y < 4; ++y)
        for (std::uint8_t x = 0; x < 4; ++x)
            texels.insert(texels.end(), {std::uint8_t(10 + 10 * x), std::uint8_t(10 + 10 * y)});
    device->writeTexture(*texture, 0, 0, std::as_bytes(std::span(texels)));
    TextureProbe probe(*device);
    struct Case {
        rhi::AddressMode mode;
        int atMinus; // texel index sampled at -0.375
        int atPlus; // ... at 1.375
    };
    for (const Case& c : {Case{rhi::AddressMode::Repeat, 2, 1}, Case{rhi::AddressMode::MirroredRepeat, 1, 2},
                          Case{rhi::AddressMode::ClampToEdge, 0, 3}}) {
        auto sampler = device->createSampler({.magFilter = rhi::Filter::Nearest,
                                              .minFilter = rhi::Filter::Nearest,
                                              .addressU = c.mode,
                                              .addressV = c.mode});
        const auto at = [&](glm::vec2 uv) { return probe.sample(*texture, *sampler, {.origin = uv}).front(); };
        const auto expected = [](int index) { return (10.0f + 10.0f * float(index)) / 255.0f; };
        const glm::vec4 a = at({-0.375f, 1.375f});
        const glm::vec4 b = at({1.375f, -0.375f});
        EXPECT_NEAR(a.r, expected(c.atMinus), 1e-3f) << "u at -0.375, mode " << int(c.mode);
        EXPECT_NEAR(a.g, expected(c.atPlus), 1e-3f) << "v at 1.375, mode " << int(c.mode);
        EXPECT_NEAR(b.r, expected(c.atPlus), 1e-3f) << "u at 1.375, mode " << int(c.mode);
        EXPECT_NEAR(b.g, expected(c.atMinus), 1e-3f) << "v at -0.375, mode " << int(c.mode);
    }
}

TEST_F(TextureTest, AnisotropyAboveTheDeviceLimitIsRefused)
{
    const float limit = device->capabilities().maxSamplerAnisotropy;
    ASSERT_GE(limit, 1.0f);
    EXPECT_NO_THROW(device->createSampler({.mipFilter = rhi::MipFilter::Linear, .maxAnisotropy = limit}));
    const std::string above = errorOf([&] {
        device->createSampler({.mipFilter = rhi::MipFilter::Linear, .maxAnisotropy = limit * 2.0f, .debugName = "a"});
    });
    EXPECT_NE(above.find("sampler 'a': maxAnisotropy"), std::string::npos) << above;
    EXPECT_NE(above.find(fmt::format("[1, {}]", limit)), std::string::npos) << above;
    EXPECT_NE(errorOf([&] { device->createSampler({.maxAnisotropy = 0.5f}); }).find("maxAnisotropy"),
              std::string::npos);
}

TEST_F(TextureTest, BadLevelsAndLodClampsAreRefused)
{
    const std::string levels =
        errorOf([&] { device->createTexture({.width = 8, .height = 2, .mipLevels = 5, .debugName = "t"}); });
    EXPECT_NE(levels.find("texture 't': mipLevels 5 is outside 1..4"), std::string::npos) << levels;
    EXPECT_NE(errorOf([&] { device->createTexture({.width = 8, .height = 2, .mipLevels = 0}); }).find("mipLevels"),
              std::string::npos);
    const std::string lod = errorOf([&] { device->createSampler({.minLod = 2.0f, .maxLod = 1.0f}); });
    EXPECT_NE(lod.find("minLod 2 and maxLod 1"), std::string::npos) << lod;

    auto texture = device->createTexture({.width = 8, .height = 2, .mipLevels = 2, .debugName = "t"});
    const std::vector<std::byte> wrongSize(8 * 2 * 4);
    const std::string upload = errorOf([&] { device->writeTexture(*texture, 0, 1, wrongSize); });
    EXPECT_NE(upload.find("level 1 of 't' (4x1 RGBA8) takes 16 bytes, got 64"), std::string::npos) << upload;
    EXPECT_NE(errorOf([&] { rhi::readTexture(*device, *texture, 0, 2); }).find("mip level 2"), std::string::npos);
    auto fewer = device->createTexture({.width = 8, .height = 2});
    auto commands = device->createCommandList();
    EXPECT_NE(errorOf([&] { commands->copyTexture(*texture, 0, *fewer, 0); }).find("with 2 levels"), std::string::npos);
}

// The CPU chain: 2 x 2 boxes in linear light for sRGB, plain averages otherwise, rounded to nearest.
TEST_F(TextureTest, GeneratedChainAveragesInLinearLightForSrgb)
{
    const std::vector<std::uint8_t> blackWhite = {0, 0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 0};
    const auto srgb = rhi::generateMipChain(rhi::Format::RGBA8_SRGB, 2, 2, 2, std::as_bytes(std::span(blackWhite)));
    const auto plain = rhi::generateMipChain(rhi::Format::RGBA8, 2, 2, 2, std::as_bytes(std::span(blackWhite)));
    ASSERT_EQ(srgb.size(), 2u);
    ASSERT_EQ(srgb[1].size(), 4u);
    EXPECT_EQ(std::uint8_t(srgb[1][0]), 188) << "linear 0.5 encoded: round(255 * 0.7354)";
    EXPECT_EQ(std::uint8_t(srgb[1][3]), 128) << "alpha is averaged linearly";
    EXPECT_EQ(std::uint8_t(plain[1][0]), 128);

    // Uploaded, each level reads back as generated.
    auto texture = device->createTexture({.width = 2, .height = 2, .mipLevels = 2, .format = rhi::Format::RGBA8_SRGB});
    rhi::writeMipChain(*device, *texture, 0, std::as_bytes(std::span(blackWhite)));
    EXPECT_EQ(rhi::readTexture(*device, *texture, 0, 1).bytes, srgb[1]);
}

} // namespace
} // namespace penumbra::testing
