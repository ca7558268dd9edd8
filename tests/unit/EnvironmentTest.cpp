// Image-based lighting's CPU math (render/Environment.hpp): the equirectangular mapping, the SH9 projection of known
// radiance (a constant and a clamped cosine lobe, whose irradiance is known in closed form), the split-sum BRDF
// table, the built-in studio environment, and reading Radiance .hdr and OpenEXR files through --environment's loader.
#include "EnvironmentOption.hpp"

#include "penumbra/imageio/ImageFiles.hpp"
#include "penumbra/render/Environment.hpp"
#include "penumbra/rhi/Error.hpp"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <limits>
#include <string>
#include <unistd.h>
#include <vector>

namespace penumbra {
namespace {

constexpr float kPi = 3.14159265358979f;

render::EnvironmentImage environmentOf(float (*radiance)(const glm::vec3&))
{
    render::EnvironmentImage image{render::kEnvironmentWidth, render::kEnvironmentHeight, {}};
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x)
            image.texels.emplace_back(radiance(render::equirectDirection((float(x) + 0.5f) / float(image.width),
                                                                         (float(y) + 0.5f) / float(image.height))));
    return image;
}

TEST(Environment, EquirectUvInvertsEquirectDirection)
{
    for (float u : {0.1f, 0.5f, 0.73f})
        for (float v : {0.05f, 0.5f, 0.9f}) {
            const glm::vec2 uv = render::equirectUv(render::equirectDirection(u, v));
            EXPECT_NEAR(uv.x, u, 1e-5f);
            EXPECT_NEAR(uv.y, v, 1e-5f);
        }
    EXPECT_NEAR(render::equirectDirection(0.5f, 0.0f).y, 1.0f, 1e-6f); // row 0 looks up
    EXPECT_NEAR(render::equirectDirection(0.5f, 0.5f).x, 1.0f, 1e-6f); // the centre looks along +x
}

TEST(Environment, Sh9OfAConstantIsBandZeroAndItsIrradianceIsPi)
{
    const render::Sh9 sh = render::projectSh9(environmentOf([](const glm::vec3&) { return 1.0f; }));
    // The integral of Y00 = 0.282095 over the sphere: 0.282095 x 4 pi.
    EXPECT_NEAR(sh[0].r, 0.282095f * 4.0f * kPi, 1e-3f);
    for (std::size_t i = 1; i < sh.size(); ++i)
        EXPECT_NEAR(sh[i].g, 0.0f, 1e-3f) << "coefficient " << i;
    for (const glm::vec3 n : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::normalize(glm::vec3(1, 2, -3))})
        EXPECT_NEAR(render::irradianceSh9(sh, n).b, kPi, 1e-3f);
}

TEST(Environment, Sh9OfACosineLobeMatchesItsClosedForm)
{
    // L = max(0, z): coefficients 0.282095 pi, 0.488603 x 2 pi / 3 (Y10) and 0.315392 x pi / 2 (Y20), none else.
    const render::Sh9 sh = render::projectSh9(environmentOf([](const glm::vec3& d) { return std::max(d.z, 0.0f); }));
    EXPECT_NEAR(sh[0].r, 0.282095f * kPi, 2e-3f);
    EXPECT_NEAR(sh[2].r, 0.488603f * 2.0f * kPi / 3.0f, 2e-3f);
    EXPECT_NEAR(sh[6].r, 0.315392f * kPi / 2.0f, 2e-3f);
    for (std::size_t i : {1u, 3u, 4u, 5u, 7u, 8u})
        EXPECT_NEAR(sh[i].r, 0.0f, 2e-3f) << "coefficient " << i;
    // Irradiance facing the lobe: the integral of cos^2 over the hemisphere, 2 pi / 3; nine coefficients come within
    // 1% (Ramamoorthi and Hanrahan 2001: the clamped cosine's bands above 2 are small). Facing away: 0.
    EXPECT_NEAR(render::irradianceSh9(sh, {0, 0, 1}).r, 2.0f * kPi / 3.0f, 0.02f * 2.0f * kPi / 3.0f);
    EXPECT_NEAR(render::irradianceSh9(sh, {0, 0, -1}).r, 0.0f, 0.03f);
    // The shader's coefficients give irradiance / pi with the polynomial of environment_light.glsl.
    const render::Sh9 c = render::diffuseShaderCoefficients(sh);
    EXPECT_NEAR(c[0].r + c[2].r + 2.0f * c[6].r, render::irradianceSh9(sh, {0, 0, 1}).r / kPi, 1e-5f);
}

TEST(Environment, BrdfTableIsAReflectanceAndAMirrorReflectsAll)
{
    const std::vector<glm::vec2> table = render::brdfTable(render::kBrdfTableSize);
    ASSERT_EQ(table.size(), std::size_t(render::kBrdfTableSize) * render::kBrdfTableSize);
    for (const glm::vec2& ab : table) {
        EXPECT_GE(ab.x, 0.0f);
        EXPECT_GE(ab.y, 0.0f);
        EXPECT_LE(ab.x + ab.y, 1.01f);
    }
    // Smooth, seen head-on: f0 A + B = 1 for f0 = 1, and B (the grazing Fresnel's share) near 0.
    const glm::vec2 mirror = table[render::kBrdfTableSize - 1];
    EXPECT_NEAR(mirror.x + mirror.y, 1.0f, 0.02f);
    EXPECT_LT(mirror.y, 0.01f);
    // Rough at grazing angles: masking takes a good share.
    EXPECT_LT(table.back().x + table.back().y, 0.9f);
}

TEST(Environment, StudioIsBrightestAtItsKeyAndDarkBelow)
{
    const render::EnvironmentImage studio = render::studioEnvironment();
    EXPECT_NO_THROW(render::validate(studio, "studio"));
    const auto radiance = [&](const glm::vec3& d) {
        const glm::vec2 uv = render::equirectUv(glm::normalize(d));
        return studio.at(std::min(std::uint32_t(uv.x * float(studio.width)), studio.width - 1),
                         std::min(std::uint32_t(uv.y * float(studio.height)), studio.height - 1));
    };
    EXPECT_GT(radiance({-0.6f, 0.6f, 0.55f}).g, 1.5f); // the key
    EXPECT_GT(radiance({0.75f, 0.3f, -0.55f}).g, 0.4f); // the fill
    EXPECT_LT(radiance({0.0f, -1.0f, 0.0f}).g, 0.05f); // the floor
    EXPECT_GT(radiance({0.0f, 1.0f, 0.0f}).g, 0.15f); // the sky
    // An upward white surface: about a quarter of white, so a sun's shadows keep their contrast beside it.
    const render::Sh9 c = render::diffuseShaderCoefficients(render::projectSh9(studio));
    const float up = c[0].g + c[1].g - c[6].g - c[8].g; // the polynomial at n = +y
    EXPECT_GT(up, 0.15f);
    EXPECT_LT(up, 0.35f);
}

TEST(Environment, ValidationNamesTheSourceAndTexel)
{
    render::EnvironmentImage image{2, 1, {glm::vec3(1.0f), glm::vec3(-1.0f)}};
    try {
        render::validate(image, "sky.hdr");
        FAIL() << "a negative texel was accepted";
    } catch (const rhi::Error& e) {
        EXPECT_NE(std::string(e.what()).find("sky.hdr"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("texel (1, 0)"), std::string::npos) << e.what();
    }
    EXPECT_THROW(render::validate(render::EnvironmentLight{nullptr, 101.0f, 0.0f}), rhi::Error);
    EXPECT_THROW(render::validate(render::EnvironmentLight{nullptr, 1.0f, std::numeric_limits<float>::quiet_NaN()}),
                 rhi::Error);
}

TEST(Environment, ReadsRadianceHdrAndNamesAMissingFile)
{
    // Radiance RGBE (Ward 1991, "Real Pixels", Graphics Gems II): flat scanlines, value = mantissa x 2^(exponent -
    // 136).
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "penumbra-environment-test.hdr";
    {
        std::ofstream out(path, std::ios::binary);
        out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
        const unsigned char texels[] = {128, 64, 32, 129, 128, 128, 128, 130};
        out.write(reinterpret_cast<const char*>(texels), sizeof texels);
    }
    const imageio::FloatImage image = imageio::readHdr(path);
    ASSERT_EQ(image.width, 2u);
    ASSERT_EQ(image.height, 1u);
    EXPECT_FLOAT_EQ(image.at(0, 0, 0), 1.0f);
    EXPECT_FLOAT_EQ(image.at(0, 0, 1), 0.5f);
    EXPECT_FLOAT_EQ(image.at(0, 0, 2), 0.25f);
    EXPECT_FLOAT_EQ(image.at(1, 0, 1), 2.0f);
    std::filesystem::remove(path);
    try {
        imageio::readHdr(path);
        FAIL() << "a missing file was read";
    } catch (const rhi::Error& e) {
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
}

// A 4 x 2 equirectangular environment as OpenEXR HALF R, G, B channels (as most HDR photographs are stored), with
// values that half holds exactly, written with OpenEXR's own writer.
std::vector<glm::vec3> writeHalfExr(const std::filesystem::path& path)
{
    constexpr int kWidth = 4, kHeight = 2;
    std::vector<glm::vec3> texels;
    for (int i = 0; i < kWidth * kHeight; ++i)
        texels.emplace_back(0.25f * float(i), 1.5f + float(i), 0.0625f * float(i * i));
    std::array<std::vector<Imath::half>, 3> channels;
    for (const glm::vec3& texel : texels)
        for (int c = 0; c < 3; ++c)
            channels[std::size_t(c)].emplace_back(texel[c]);
    Imf::Header header(kWidth, kHeight);
    Imf::FrameBuffer frame;
    for (int c = 0; c < 3; ++c) {
        const char* name = c == 0 ? "R" : c == 1 ? "G" : "B";
        header.channels().insert(name, Imf::Channel(Imf::HALF));
        frame.insert(name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(channels[std::size_t(c)].data()),
                                      sizeof(Imath::half), sizeof(Imath::half) * kWidth));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(kHeight);
    return texels;
}

std::filesystem::path temporary(const std::string& name)
{
    return std::filesystem::temp_directory_path() / ("penumbra-" + std::to_string(::getpid()) + "-" + name);
}

// --environment FILE.exr reads the texels written, row 0 at the top, R, G and B as the file names them; a file cut
// half-way (a download that stopped early) is refused with a message naming it.
TEST(Environment, TheEnvironmentLoaderReadsAnExrsTexelsAndNamesACorruptOne)
{
    const std::filesystem::path path = temporary("sky.exr");
    const std::vector<glm::vec3> written = writeHalfExr(path);
    const render::EnvironmentLight light = apps::environmentOf(path.string(), false, 1.0f, 0.0f, "--environment");
    ASSERT_TRUE(light.image);
    EXPECT_EQ(light.image->width, 4u);
    EXPECT_EQ(light.image->height, 2u);
    EXPECT_EQ(light.image->texels, written);

    const std::filesystem::path cut = temporary("cut.exr");
    {
        std::ifstream in(path, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    }
    try {
        apps::environmentOf(cut.string(), false, 1.0f, 0.0f, "--environment");
        FAIL() << "a corrupt .exr was read";
    } catch (const rhi::Error& e) {
        EXPECT_NE(std::string(e.what()).find(cut.string()), std::string::npos) << e.what();
    }
    std::filesystem::remove(path);
    std::filesystem::remove(cut);
}

} // namespace
} // namespace penumbra
