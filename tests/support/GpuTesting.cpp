#include "GpuTesting.hpp"

#include "ImageFiles.hpp"

#include <cstdlib>
#include <fmt/format.h>

namespace penumbra::testing {
namespace {
std::string& currentConfiguration()
{
    static std::string name = "vulkan";
    return name;
}
} // namespace

const std::string& configuration() { return currentConfiguration(); }

void setConfiguration(std::string name) { currentConfiguration() = std::move(name); }

std::unique_ptr<rhi::Device> createValidatedDevice(const std::string& name)
{
    rhi::DeviceDesc desc = rhi::parseConfiguration(name);
    desc.validation = true;
    return createDevice(desc);
}

void expectNoDebugMessages(rhi::Device& device)
{
    for (const std::string& message : device.debugMessages())
        ADD_FAILURE() << rhi::configurationName(device.desc()) << " debug message: " << message;
}

void GpuTest::SetUp() { device = createValidatedDevice(configuration()); }

void GpuTest::TearDown()
{
    if (device)
        expectNoDebugMessages(*device);
}

Rgba pixel(const rhi::Image& image, std::uint32_t x, std::uint32_t y)
{
    const std::byte* p = image.texel(x, y);
    return {std::uint8_t(p[0]), std::uint8_t(p[1]), std::uint8_t(p[2]), std::uint8_t(p[3])};
}

float luminance(const rhi::Image& image, std::uint32_t x, std::uint32_t y)
{
    const Rgba c = pixel(image, x, y);
    return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
}

std::string describe(Rgba c) { return fmt::format("rgba({}, {}, {}, {})", c[0], c[1], c[2], c[3]); }

std::string savePicture(const rhi::Image& image, const std::string& name)
{
    const char* root = std::getenv("PENUMBRA_TEST_OUTPUT");
    const std::string path = fmt::format("{}/{}.png", root ? root : "test-output", name);
    apps::writePng(path, image);
    return path;
}

} // namespace penumbra::testing
