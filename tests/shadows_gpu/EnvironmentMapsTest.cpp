// The environment's specular chain as the GPU prefilters it (render/src/EnvironmentMaps.hpp), once per configuration:
// level 0 is the uploaded source bit for bit, and a constant environment stays that constant at every roughness.
#include "EnvironmentMaps.hpp"
#include "GpuTesting.hpp"

#include "penumbra/render/LitUniforms.hpp"
#include "penumbra/rhi/Image.hpp"

#include <glm/gtc/packing.hpp>

#include <cstring>
#include <gtest/gtest.h>

namespace penumbra {
namespace {

using EnvironmentMapsTest = testing::GpuTest;

// Channel c of texel i of an RGBA16F read-back.
float halfAt(const rhi::Image& image, std::size_t i, std::size_t c)
{
    std::uint16_t bits = 0;
    std::memcpy(&bits, image.bytes.data() + (i * 4 + c) * sizeof bits, sizeof bits);
    return glm::unpackHalf1x16(bits);
}

TEST_F(EnvironmentMapsTest, LevelZeroOfTheSpecularChainIsTheSource)
{
    render::EnvironmentMaps maps(*device);
    const auto studio = std::make_shared<const render::EnvironmentImage>(render::studioEnvironment());
    ASSERT_TRUE(maps.use(studio).has_value());
    EXPECT_FALSE(maps.use(studio).has_value()) << "the same image was prefiltered again";
    const rhi::Image source = rhi::readTexture(*device, maps.source());
    const rhi::Image level0 = rhi::readTexture(*device, maps.specular());
    ASSERT_EQ(source.width, render::kEnvironmentWidth);
    EXPECT_TRUE(source.bytes == level0.bytes);
}

TEST_F(EnvironmentMapsTest, AConstantEnvironmentStaysConstantAtEveryRoughness)
{
    render::EnvironmentMaps maps(*device);
    auto image = std::make_shared<render::EnvironmentImage>();
    image->width = 64;
    image->height = 32;
    image->texels.assign(64 * 32, glm::vec3(0.5f, 1.0f, 2.0f));
    maps.use(image);
    for (std::uint32_t level = 0; level < render::kEnvironmentLevels; ++level) {
        const rhi::Image picture = rhi::readTexture(*device, maps.specular(), 0, level);
        ASSERT_EQ(picture.width, render::kEnvironmentWidth >> level);
        for (std::size_t i = 0; i < std::size_t(picture.width) * picture.height; ++i)
            for (std::size_t c = 0; c < 3; ++c)
                ASSERT_NEAR(halfAt(picture, i, c), image->texels[0][int(c)], 2e-3f * image->texels[0][int(c)])
                    << "level " << level << ", texel " << i << ", channel " << c;
    }
}

} // namespace
} // namespace penumbra
