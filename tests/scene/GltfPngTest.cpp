// The loader's PNG pictures: its own inflate-and-unfilter path (gltf/src/GltfPng.hpp) and stb_image's give the texels
// that were written, for every row filter.
#include "GltfImages.hpp"
#include "GltfPng.hpp"

#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include <random>
#include <vector>

namespace penumbra::gltf {
namespace {

// A PNG of `channels` 8-bit channels, every row written with `filter` (0 to 4, W3C PNG section 9.2).
std::vector<std::uint8_t> pngOf(const std::vector<std::uint8_t>& texels, int width, int height, int channels,
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

TEST(GltfPngTest, EveryRowFilterGivesTheWrittenTexels)
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
            const std::vector<std::uint8_t> png = pngOf(texels, width, height, channels, filter);
            // Grey is stb_image's alone; truecolour is the loader's own, and stb_image's where it declines.
            EXPECT_EQ(decodeTruecolourPng(png).has_value(), channels != 1) << channels << " channels";
            tinygltf::Image image;
            ASSERT_EQ(decodeImage(png, image), "") << channels << " channels, filter " << filter;
            EXPECT_EQ(image.image, expected) << channels << " channels, filter " << filter;
        }
    }
}

// A picture cut short, or with its zlib data damaged, is left to stb_image (which says what is wrong).
TEST(GltfPngTest, DamagedPicturesAreLeftToStbImage)
{
    const std::vector<std::uint8_t> texels(4 * 4 * 4, 200);
    std::vector<std::uint8_t> png = pngOf(texels, 4, 4, 4, 1);
    const std::vector<std::uint8_t> cut(png.begin(), png.begin() + std::ptrdiff_t(png.size() / 2));
    EXPECT_FALSE(decodeTruecolourPng(cut).has_value());
    png[41] ^= 0xff; // inside the IDAT chunk's zlib data (signature 8, IHDR 25, IDAT length and type 8)
    EXPECT_FALSE(decodeTruecolourPng(png).has_value());
}

} // namespace
} // namespace penumbra::gltf
