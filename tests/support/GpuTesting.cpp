#include "GpuTesting.hpp"

#include "penumbra/parity/ImageFiles.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <cstdlib>
#include <string_view>
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
    rhi::DeviceDesc desc = penumbra::parseConfiguration(name);
    desc.validation = true;
    return createDevice(desc);
}

void expectNoDebugMessages(rhi::Device& device)
{
    for (const std::string& message : device.debugMessages())
        ADD_FAILURE() << penumbra::configurationName(device.desc()) << " debug message: " << message;
}

std::vector<SkippedConfiguration>
forEachConfiguration(const std::function<void(rhi::Device& device, const std::string& configuration)>& use)
{
    std::vector<SkippedConfiguration> skipped;
    for (const std::string& name : compiledConfigurations()) {
        std::unique_ptr<rhi::Device> device;
        try {
            device = createValidatedDevice(name);
        } catch (const rhi::UnsupportedError& e) {
            skipped.push_back({name, e.what()});
            continue;
        }
        use(*device, name);
        expectNoDebugMessages(*device);
    }
    return skipped;
}

std::string errorOf(const std::function<void()>& f)
{
    try {
        f();
    } catch (const rhi::Error& e) {
        return e.what();
    }
    return "(no error)";
}

const std::vector<std::string>& compiledConfigurations()
{
    // PENUMBRA_TEST_CONFIGURATIONS is tests/CMakeLists.txt's `configurations` list, comma-separated.
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        std::string_view rest = PENUMBRA_TEST_CONFIGURATIONS;
        while (!rest.empty()) {
            const std::size_t comma = std::min(rest.find(','), rest.size());
            out.emplace_back(rest.substr(0, comma));
            rest.remove_prefix(std::min(comma + 1, rest.size()));
        }
        return out;
    }();
    return names;
}

void reportSkipped(const std::vector<SkippedConfiguration>& skipped)
{
    if (skipped.empty())
        return;
    std::string reasons;
    for (const SkippedConfiguration& s : skipped)
        reasons += fmt::format("\n  {}: {}", s.name, s.reason);
    GTEST_SKIP() << skipped.size() << " of " << compiledConfigurations().size()
                 << " compiled configurations unsupported by the driver:" << reasons;
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

std::uint32_t lowestMultisampleCount(const rhi::Capabilities& caps, std::span<const rhi::Format> targets)
{
    const std::uint32_t offered = caps.sampleCounts(targets);
    for (std::uint32_t count = 2; count <= 8; count *= 2)
        if (offered & count)
            return count;
    return 0;
}

std::string savePicture(const rhi::Image& image, const std::string& name)
{
    const char* root = std::getenv("PENUMBRA_TEST_OUTPUT");
    const std::string path = fmt::format("{}/{}.png", root ? root : "test-output", name);
    parity::writePng(path, image);
    return path;
}

std::size_t differingPixels(const rhi::Image& a, const rhi::Image& b, int tolerance)
{
    std::size_t differing = 0;
    for (std::size_t i = 0; i + 3 < a.bytes.size(); i += 4) {
        bool differs = false;
        for (std::size_t c = 0; c < 3; ++c)
            differs |=
                std::abs(std::to_integer<int>(a.bytes[i + c]) - std::to_integer<int>(b.bytes[i + c])) > tolerance;
        differing += differs ? 1 : 0;
    }
    return differing;
}

double differingShare(const rhi::Image& a, const rhi::Image& b, int tolerance)
{
    return static_cast<double>(differingPixels(a, b, tolerance)) / static_cast<double>(a.bytes.size() / 4);
}

bool reversedTwins(const std::string& a, const std::string& b) { return a + "-reversed" == b || b + "-reversed" == a; }

} // namespace penumbra::testing
