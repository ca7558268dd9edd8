#include "GpuTesting.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/MemorySize.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

using OutOfMemoryTest = GpuTest;

constexpr std::uint32_t kAtlasSide = 8192;

// After the refusal the device still creates, clears and reads back an atlas: the next smaller request succeeds.
void expectUsable(rhi::Device& device)
{
    auto atlas = device.createTexture({.width = 256,
                                       .height = 256,
                                       .format = rhi::Format::D32F,
                                       .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                       .debugName = "atlas after the refusal"});
    auto framebuffer = device.createFramebuffer({.depth = {atlas.get(), 0}});
    auto commands = device.createCommandList();
    commands->beginPass({.framebuffer = framebuffer.get(), .clearColor = std::nullopt});
    commands->endPass();
    device.submit(*commands);
    const rhi::DepthImage depth = rhi::readDepth(device, *atlas);
    EXPECT_EQ(depth.depth.at(0), float(device.conventions().clearDepth()));
}

// Cube-map atlases of 8192^2 D32F faces, as many cubes as it takes to pass the device's memory (each face is
// 256 MiB): refused before the driver is asked, naming the texture and its size.
TEST_F(OutOfMemoryTest, CubeAtlasesBeyondTheDeviceMemoryAreANamedError)
{
    const rhi::Capabilities& caps = device->capabilities();
    ASSERT_GT(caps.deviceMemoryBytes, 0u) << caps.device << " reports no memory size";
    constexpr std::uint64_t kFaceBytes = std::uint64_t(kAtlasSide) * kAtlasSide * 4;
    const std::uint32_t cubes = std::uint32_t(caps.deviceMemoryBytes / (6 * kFaceBytes)) + 1;
    if (kAtlasSide > caps.maxCubeSize || cubes * 6 > caps.maxTextureLayers)
        GTEST_SKIP() << caps.device << ": " << cubes << " cubes of " << kAtlasSide << "^2 are past its limits";
    const rhi::TextureDesc huge{.width = kAtlasSide,
                                .height = kAtlasSide,
                                .layers = cubes * 6,
                                .cube = true,
                                .format = rhi::Format::D32F,
                                .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                .debugName = "point shadow cubes"};
    const std::string message = errorOf([&] { device->createTexture(huge); });
    EXPECT_NE(message.find(fmt::format("texture 'point shadow cubes' (8192 x 8192, {} layers, D32F, {})", cubes * 6,
                                       rhi::byteSize(rhi::textureBytes(huge)))),
              std::string::npos)
        << message;
    EXPECT_NE(message.find(
                  fmt::format("does not fit in the device's {} of memory", rhi::byteSize(caps.deviceMemoryBytes))),
              std::string::npos)
        << message;
    expectUsable(*device);
}

TEST_F(OutOfMemoryTest, BufferBeyondTheDeviceMemoryIsANamedError)
{
    const std::uint64_t size = device->capabilities().deviceMemoryBytes + 1;
    const rhi::BufferDesc desc{.size = size, .usage = rhi::BufferUsage::Vertex, .debugName = "vertices"};
    const std::string message = errorOf([&] { device->createBuffer(desc); });
    EXPECT_NE(message.find(fmt::format("buffer 'vertices' ({}) does not fit", rhi::byteSize(size))), std::string::npos)
        << message;
    expectUsable(*device);
}

} // namespace
} // namespace penumbra::testing
