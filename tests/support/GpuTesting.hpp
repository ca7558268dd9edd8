#pragma once

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/Image.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <gtest/gtest.h>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace penumbra::testing {

// The configuration this process tests (--configuration NAME, default vulkan).
const std::string& configuration();
void setConfiguration(std::string name);

// The named configurations this build compiles (the PENUMBRA_VULKAN and PENUMBRA_OPENGL options), in
// penumbra::namedConfigurations() order: what a cross-configuration test has to run, not merely try.
const std::vector<std::string>& compiledConfigurations();

// A compiled configuration the driver refused (rhi::UnsupportedError), and its message.
struct SkippedConfiguration {
    std::string name;
    std::string reason;
};
// Marks the running test skipped, naming each configuration and reason, when there are any; failures
// the test recorded for the configurations that ran still fail it (GoogleTest's skip does not clear them).
void reportSkipped(const std::vector<SkippedConfiguration>& skipped);

// The message of the rhi::Error that `f` throws, or "(no error)" when it throws none.
std::string errorOf(const std::function<void()>& f);

// A device with validation / debug output on; any message it records fails the test.
std::unique_ptr<rhi::Device> createValidatedDevice(const std::string& configuration);
void expectNoDebugMessages(rhi::Device& device);

// Calls `use` with a validated device of each compiled configuration in turn, then fails the test for any debug
// message it recorded; returns the configurations whose device the driver refused (rhi::UnsupportedError).
std::vector<SkippedConfiguration>
forEachConfiguration(const std::function<void(rhi::Device& device, const std::string& configuration)>& use);

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    std::unique_ptr<rhi::Device> device;
};

using Rgba = std::array<std::uint8_t, 4>;
Rgba pixel(const rhi::Image& image, std::uint32_t x, std::uint32_t y);
// Rec. 709 luma of an RGBA8 pixel's stored (sRGB-encoded) values, 0..255.
float luminance(const rhi::Image& image, std::uint32_t x, std::uint32_t y);
std::string describe(Rgba c);

// Pixels whose red, green or blue differ by more than `tolerance` steps; as a share of all pixels.
std::size_t differingPixels(const rhi::Image& a, const rhi::Image& b, int tolerance);
double differingShare(const rhi::Image& a, const rhi::Image& b, int tolerance);

// Whether two configuration names are one backend with the two depth mappings ("vulkan", "vulkan-reversed").
bool reversedTwins(const std::string& a, const std::string& b);

// The lowest sample count above 1 that the device offers for every one of `targets` (Capabilities::sampleCounts);
// 0 where it offers none.
std::uint32_t lowestMultisampleCount(const rhi::Capabilities& caps, std::span<const rhi::Format> targets);

// Writes the picture under $PENUMBRA_TEST_OUTPUT (or ./test-output) and returns its path, for failure messages.
std::string savePicture(const rhi::Image& image, const std::string& name);

} // namespace penumbra::testing
