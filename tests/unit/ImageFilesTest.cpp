#include "penumbra/imageio/ImageFiles.hpp"
#include "penumbra/rhi/Error.hpp"

#include "ScratchFolder.hpp"

#include <filesystem>
#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;
namespace imageio = penumbra::imageio;
namespace rhi = penumbra::rhi;

fs::path imageScratch(const char* name) { return penumbra::testing::scratchFolder("image-files-tests", name); }

// A picture whose every byte differs from its neighbours', so a swapped channel or flipped row shows.
rhi::Image gradient(std::uint32_t width, std::uint32_t height)
{
    rhi::Image image{width, height, rhi::Format::RGBA8, std::vector<std::byte>(std::size_t(width) * height * 4)};
    for (std::size_t i = 0; i < image.bytes.size(); ++i)
        image.bytes[i] = std::byte(i * 7 % 251);
    return image;
}

// The call throws rhi::Error with `text` in its message.
template <typename Call>
void expectFailure(Call call, const std::string& text)
{
    try {
        call();
        ADD_FAILURE() << "no error, expected one naming '" << text << "'";
    } catch (const rhi::Error& e) {
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
}

TEST(ImageFiles, PngKeepsEveryByteAndRowOrder)
{
    const fs::path file = imageScratch("png") / "gradient.png";
    const rhi::Image image = gradient(13, 5);
    imageio::writePngFile(file, image);
    const rhi::Image read = imageio::readPng(file);
    EXPECT_EQ(read.width, 13u);
    EXPECT_EQ(read.height, 5u);
    EXPECT_EQ(read.bytes, image.bytes);
}

TEST(ImageFiles, PngEncodingIsTheSameBytesEveryTime)
{
    EXPECT_EQ(imageio::encodePng(gradient(9, 4)), imageio::encodePng(gradient(9, 4)));
}

TEST(ImageFiles, ExrKeepsFloatValuesAndChannelNames)
{
    const fs::path file = imageScratch("exr") / "depth.exr";
    imageio::FloatImage depth{3, 2, {"Z"}, {0.0f, 0.25f, 1.0f, 1e-7f, 0.999999f, 0.5f}};
    imageio::writeExrFile(file, depth);
    const imageio::FloatImage read = imageio::readExr(file);
    EXPECT_EQ(read.width, 3u);
    EXPECT_EQ(read.height, 2u);
    EXPECT_EQ(read.channels, depth.channels);
    EXPECT_EQ(read.values, depth.values);
    EXPECT_EQ(read.at(1, 1, 0), 0.999999f);
}

TEST(ImageFiles, ExrChannelsAreFoundByName)
{
    const fs::path file = imageScratch("rgba") / "picture.exr";
    imageio::FloatImage picture{1, 1, {"R", "G", "B", "A"}, {0.1f, 0.2f, 0.3f, 1.0f}};
    imageio::writeExrFile(file, picture);
    const imageio::FloatImage read = imageio::readExr(file);
    ASSERT_TRUE(read.channelIndex("G"));
    EXPECT_EQ(read.at(0, 0, *read.channelIndex("G")), 0.2f);
    EXPECT_EQ(read.at(0, 0, *read.channelIndex("A")), 1.0f);
    EXPECT_FALSE(read.channelIndex("Z"));
}

TEST(ImageFiles, BadInputIsANamedError)
{
    const fs::path folder = imageScratch("bad");
    rhi::Image grey{2, 2, rhi::Format::R8, std::vector<std::byte>(4)};
    expectFailure([&] { imageio::encodePng(grey); }, "PNG needs RGBA8");
    expectFailure([&] { imageio::encodeExr({2, 2, {"Z"}, {1.0f}}); }, "needs 4 values, has 1");
    expectFailure([&] { imageio::readPng(folder / "missing.png"); }, "missing.png: cannot read");
    imageio::writePngFile(folder / "not-an.exr", gradient(2, 2));
    expectFailure([&] { imageio::readExr(folder / "not-an.exr"); }, "not-an.exr: cannot read");
    expectFailure([&] { imageio::writePngFile(folder / "grey.png", grey); },
                  "cannot write " + (folder / "grey.png").string());
    EXPECT_FALSE(fs::exists(folder / "grey.png"));
}

} // namespace
