// The tools' --validate (apps::toolDeviceDesc): with it a misuse made through the device's native handles is
// reported as the validation layer or debug output words it; without it the same misuse goes unreported and the
// device still draws, which is how the tools run by default (the layer slows every call).
#include "ToolDevices.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/opengl/Native.hpp"
#include "penumbra/vulkan/Native.hpp"

#include <gtest/gtest.h>

namespace penumbra::apps {
namespace {

// The misuse of DebugMessagesTest, per backend: wide lines the device did not enable (Vulkan,
// VUID-vkCmdSetLineWidth-lineWidth-00788), a buffer name glGenBuffers never returned (GL_INVALID_OPERATION).
void misuse(const std::string& configuration, rhi::Device& device, rhi::CommandList& commands)
{
    if (configuration == "vulkan") {
        vkCmdSetLineWidth(vulkan::native(commands), 4.0f);
    } else {
        opengl::makeCurrent(device);
        opengl::glFunctions(device).BindBuffer(GL_ARRAY_BUFFER, 123456);
    }
}

// Clears a small target after the misuse and submits: the device goes on working.
std::size_t messagesAfterMisuse(const std::string& configuration, bool validate)
{
    auto device = createDevice(toolDeviceDesc(configuration, validate));
    auto commands = device->createCommandList();
    misuse(configuration, *device, *commands);
    auto target = device->createTexture({.width = 4, .height = 4, .usage = rhi::TextureUsage::RenderTarget});
    const rhi::Attachment color{target.get(), 0};
    auto framebuffer = device->createFramebuffer({.colors = {&color, 1}});
    commands->beginPass({.framebuffer = framebuffer.get(), .clearColor = glm::vec4(1.0f)});
    commands->endPass();
    device->submit(*commands);
    return device->debugMessages().size();
}

class ToolValidationTest : public ::testing::TestWithParam<std::string> {};

TEST_P(ToolValidationTest, AMisuseIsReportedWithValidateOnly)
{
    EXPECT_GT(messagesAfterMisuse(GetParam(), true), 0u) << "--validate did not report the misuse";
    EXPECT_EQ(messagesAfterMisuse(GetParam(), false), 0u) << "without --validate the misuse was still reported";
}

INSTANTIATE_TEST_SUITE_P(Backends, ToolValidationTest, ::testing::Values("vulkan", "opengl"));

} // namespace
} // namespace penumbra::apps
