// The loader's PNG pictures (gltf/src/GltfPng.hpp, libpng) give the texels stb_image, the loader's decoder before
// libpng, gives: for the pictures the loader tests write (stb_image_write, every row filter) and for pictures of every
// colour type, bit depth, interlace and transparency written by libpng.
#include "GltfImages.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <png.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <csetjmp>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace penumbra::gltf {
namespace {

// A PNG of `channels` 8-bit channels, every row written with `filter` (0 to 4, W3C PNG section 9.2), as
// imageio::encodePng (which the loader tests' GltfBuilder uses) writes them.
std::vector<std::uint8_t> stbPngOf(const std::vector<std::uint8_t>& texels, int width, int height, int channels,
                                   int filter)
{
    std::vector<std::uint8_t> bytes;
    const auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<std::uint8_t>*>(context);
        out->insert(out->end(), static_cast<std::uint8_t*>(data), static_cast<std::uint8_t*>(data) + size);
    };
    stbi_write_force_png_filter = filter;
    stbi_write_png_to_func(append, &bytes, width, height, channels, texels.data(), width * channels);
    stbi_write_force_png_filter = -1;
    return bytes;
}

// The texels stb_image decodes `png` to, as RGBA8 the way the loader converted them before libpng: grey spread over
// RGB, a missing alpha opaque, 16-bit channels rounded to nearest, (v + 128) / 257.
std::vector<unsigned char> stbTexelsOf(const std::vector<std::uint8_t>& png)
{
    const int size = int(png.size());
    const bool wide = stbi_is_16_bit_from_memory(png.data(), size) != 0;
    int width = 0, height = 0, channels = 0;
    void* decoded = wide ? static_cast<void*>(stbi_load_16_from_memory(png.data(), size, &width, &height, &channels, 0))
                         : static_cast<void*>(stbi_load_from_memory(png.data(), size, &width, &height, &channels, 0));
    if (!decoded)
        return {};
    const std::unique_ptr<void, decltype(&stbi_image_free)> owned(decoded, &stbi_image_free);
    const auto channel = [&](std::size_t i) {
        return wide ? std::uint8_t((static_cast<const std::uint16_t*>(decoded)[i] + 128) / 257)
                    : static_cast<const std::uint8_t*>(decoded)[i];
    };
    std::vector<unsigned char> rgba;
    const auto count = std::size_t(channels);
    for (std::size_t t = 0; t < std::size_t(width) * std::size_t(height); ++t) {
        const bool grey = channels <= 2;
        rgba.insert(rgba.end(),
                    {channel(t * count), channel(t * count + (grey ? 0 : 1)), channel(t * count + (grey ? 0 : 2)),
                     channels == 2 || channels == 4 ? channel(t * count + count - 1) : std::uint8_t(255)});
    }
    return rgba;
}

TEST(GltfPngTest, EveryRowFilterOfTheLoaderTestsPicturesGivesTheWrittenTexels)
{
    const int width = 13, height = 7;
    std::mt19937 random(45);
    for (const int channels : {1, 3, 4}) {
        std::vector<std::uint8_t> texels(std::size_t(width) * height * channels);
        for (std::uint8_t& value : texels)
            value = std::uint8_t(random());
        std::vector<unsigned char> expected;
        for (std::size_t t = 0; t < texels.size() / std::size_t(channels); ++t) {
            const std::uint8_t* texel = texels.data() + t * std::size_t(channels);
            expected.insert(expected.end(), {texel[0], texel[channels == 1 ? 0 : 1], texel[channels == 1 ? 0 : 2],
                                             channels == 4 ? texel[3] : std::uint8_t(255)});
        }
        for (int filter = 0; filter <= 4; ++filter) {
            const std::vector<std::uint8_t> png = stbPngOf(texels, width, height, channels, filter);
            tinygltf::Image image;
            ASSERT_EQ(decodeImage(png, image), "") << channels << " channels, filter " << filter;
            EXPECT_EQ(image.width, width);
            EXPECT_EQ(image.height, height);
            EXPECT_EQ(image.image, expected) << channels << " channels, filter " << filter;
            EXPECT_EQ(stbTexelsOf(png), expected) << channels << " channels, filter " << filter;
        }
    }
}

// A picture for libpng to write: random samples of the colour type and depth, optionally interlaced (Adam7), with a
// tRNS chunk (palette alphas, or the first texel's grey or RGB as the transparent key), a gAMA chunk of 1.0 (which
// must change no texel), every row with one filter (-1: libpng's choice).
struct PngTestCase {
    int colourType = PNG_COLOR_TYPE_RGB;
    int depth = 8;
    bool interlaced = false;
    bool transparency = false;
    bool gamma = false;
    int filter = -1;
    std::uint32_t width = 13, height = 7;
};

void appendPngTestBytes(png_structp png, png_bytep data, std::size_t size)
{
    auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + size);
}

// Plain data only in this frame: libpng longjmps back to its setjmp on an error.
bool writePngTestRows(png_structp png, png_infop info, const PngTestCase* c, png_bytepp rows, png_colorp palette,
                      png_bytep paletteAlphas, png_color_16p key)
{
    if (setjmp(png_jmpbuf(png)))
        return false;
    png_set_IHDR(png, info, c->width, c->height, c->depth, c->colourType,
                 c->interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (c->colourType == PNG_COLOR_TYPE_PALETTE)
        png_set_PLTE(png, info, palette, 1 << c->depth);
    if (c->transparency)
        png_set_tRNS(png, info, paletteAlphas, (1 << c->depth) / 2, key);
    if (c->gamma)
        png_set_gAMA(png, info, 1.0);
    if (c->filter >= 0)
        png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE << c->filter);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    return true;
}

std::vector<std::uint8_t> libpngPngOf(const PngTestCase& c, std::uint32_t seed)
{
    const int samples = c.colourType == PNG_COLOR_TYPE_RGB          ? 3
                        : c.colourType == PNG_COLOR_TYPE_RGB_ALPHA  ? 4
                        : c.colourType == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                                                                    : 1;
    const std::size_t rowBytes = (std::size_t(c.width) * samples * c.depth + 7) / 8;
    std::vector<std::uint8_t> samplesOf(rowBytes * c.height);
    std::mt19937 random(seed);
    for (std::uint8_t& value : samplesOf)
        value = std::uint8_t(random());
    std::vector<png_bytep> rows;
    for (std::uint32_t y = 0; y < c.height; ++y)
        rows.push_back(samplesOf.data() + y * rowBytes);
    std::vector<png_color> palette(256);
    std::vector<png_byte> paletteAlphas(256);
    for (std::size_t i = 0; i < palette.size(); ++i) {
        palette[i] = {std::uint8_t(random()), std::uint8_t(random()), std::uint8_t(random())};
        paletteAlphas[i] = std::uint8_t(random());
    }
    // The key is the first texel's samples, so some texels are transparent.
    const auto sample = [&](int i) {
        return c.depth == 16  ? png_uint_16(samplesOf[2 * i] << 8 | samplesOf[2 * i + 1])
               : c.depth == 8 ? png_uint_16(samplesOf[i])
                              : png_uint_16(samplesOf[0] >> (8 - c.depth));
    };
    png_color_16 key{0, sample(0), sample(1), sample(2), sample(0)};
    std::vector<std::uint8_t> bytes;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_set_write_fn(png, &bytes, appendPngTestBytes, nullptr);
    const bool written = writePngTestRows(png, info, &c, rows.data(), palette.data(), paletteAlphas.data(), &key);
    png_destroy_write_struct(&png, &info);
    return written ? bytes : std::vector<std::uint8_t>{};
}

TEST(GltfPngTest, EveryColourTypeDepthAndInterlaceGivesStbImagesTexels)
{
    struct Kind {
        int colourType;
        std::vector<int> depths;
    };
    const std::vector<Kind> kinds{{PNG_COLOR_TYPE_GRAY, {1, 2, 4, 8, 16}},
                                  {PNG_COLOR_TYPE_RGB, {8, 16}},
                                  {PNG_COLOR_TYPE_PALETTE, {1, 2, 4, 8}},
                                  {PNG_COLOR_TYPE_GRAY_ALPHA, {8, 16}},
                                  {PNG_COLOR_TYPE_RGB_ALPHA, {8, 16}}};
    std::uint32_t seed = 0;
    int checked = 0;
    for (const Kind& kind : kinds)
        for (const int depth : kind.depths)
            for (const bool interlaced : {false, true})
                for (const bool transparency : {false, true}) {
                    if (transparency && (kind.colourType & PNG_COLOR_MASK_ALPHA))
                        continue; // tRNS is not allowed with an alpha channel (W3C PNG, section 11.3.2.1)
                    for (const std::uint32_t size : {13u, 2u}) {
                        const PngTestCase c{kind.colourType, depth, interlaced, transparency,
                                            seed % 3 == 0,   -1,    size,       size == 2 ? 3u : 7u};
                        const std::vector<std::uint8_t> png = libpngPngOf(c, ++seed);
                        const std::string what =
                            fmt::format("colour type {}, {} bits, {}interlaced{}{}, {}x{}", c.colourType, depth,
                                        interlaced ? "" : "not ", transparency ? ", tRNS" : "",
                                        c.gamma ? ", gAMA 1" : "", c.width, c.height);
                        ASSERT_FALSE(png.empty()) << what;
                        const std::vector<unsigned char> expected = stbTexelsOf(png);
                        ASSERT_EQ(expected.size(), std::size_t(c.width) * c.height * 4) << what;
                        tinygltf::Image image;
                        ASSERT_EQ(decodeImage(png, image), "") << what;
                        EXPECT_EQ(image.image, expected) << what;
                        if (transparency && kind.colourType != PNG_COLOR_TYPE_PALETTE) {
                            EXPECT_EQ(image.image[3], 0) << what << ": the first texel is the transparent key";
                        }
                        ++checked;
                    }
                }
    EXPECT_EQ(checked, 104);
    // Every row filter on 16-bit RGBA, whose filters work on bytes two apart from the texel's.
    for (int filter = 0; filter <= 4; ++filter) {
        const PngTestCase c{PNG_COLOR_TYPE_RGB_ALPHA, 16, filter % 2 == 1, false, false, filter};
        const std::vector<std::uint8_t> png = libpngPngOf(c, ++seed);
        tinygltf::Image image;
        ASSERT_EQ(decodeImage(png, image), "") << "filter " << filter;
        EXPECT_EQ(image.image, stbTexelsOf(png)) << "filter " << filter;
    }
}

// Every 16-bit value rounds to the nearest 8-bit one, (v + 128) / 257, as the loader rounded them before libpng.
TEST(GltfPngTest, SixteenBitsRoundToNearest)
{
    const PngTestCase c{PNG_COLOR_TYPE_GRAY, 16, false, false, false, 0, 256, 256};
    std::vector<std::uint8_t> samples(std::size_t(65536) * 2);
    for (std::size_t v = 0; v < 65536; ++v) {
        samples[2 * v] = std::uint8_t(v >> 8);
        samples[2 * v + 1] = std::uint8_t(v);
    }
    std::vector<png_bytep> rows;
    for (std::size_t y = 0; y < 256; ++y)
        rows.push_back(samples.data() + y * 512);
    std::vector<std::uint8_t> png;
    png_structp writer = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(writer);
    png_set_write_fn(writer, &png, appendPngTestBytes, nullptr);
    const bool written = writePngTestRows(writer, info, &c, rows.data(), nullptr, nullptr, nullptr);
    png_destroy_write_struct(&writer, &info);
    ASSERT_TRUE(written);
    tinygltf::Image image;
    ASSERT_EQ(decodeImage(png, image), "");
    ASSERT_EQ(image.image.size(), std::size_t(65536) * 4);
    for (std::size_t v = 0; v < 65536; ++v)
        ASSERT_EQ(image.image[4 * v], (v + 128) / 257) << v;
}

// A picture cut short, or with its zlib data damaged, is refused with libpng's message; a damaged checksum alone
// is not (stb_image checked none, so such pictures decoded before libpng too).
TEST(GltfPngTest, DamagedPicturesAreRefusedWithLibpngsMessage)
{
    const std::vector<std::uint8_t> texels(4 * 4 * 4, 200);
    const std::vector<std::uint8_t> png = stbPngOf(texels, 4, 4, 4, 1);
    tinygltf::Image image;
    const std::vector<std::uint8_t> cut(png.begin(), png.begin() + std::ptrdiff_t(png.size() / 2));
    EXPECT_EQ(decodeImage(cut, image).rfind("does not decode: libpng: ", 0), 0u) << decodeImage(cut, image);
    std::vector<std::uint8_t> damaged = png;
    damaged[43] ^= 0xff; // inside the IDAT chunk's zlib data (signature 8, IHDR 25, IDAT length and type 8, zlib 2)
    EXPECT_EQ(decodeImage(damaged, image).rfind("does not decode: libpng: ", 0), 0u) << decodeImage(damaged, image);
    std::vector<std::uint8_t> checksum = png;
    checksum[29] ^= 0xff; // IHDR's CRC
    checksum[checksum.size() - 13] ^= 0xff; // the last IDAT's CRC, before IEND's 12 bytes
    ASSERT_EQ(decodeImage(checksum, image), "");
    EXPECT_EQ(image.image, std::vector<unsigned char>(texels.begin(), texels.end()));
}

} // namespace
} // namespace penumbra::gltf
