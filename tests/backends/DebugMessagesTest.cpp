// The plumbing behind "a validation message is a failing test": a real API misuse made through
// each backend's native handles must be recorded, and raised at submit with throwOnDebugMessage.
#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/opengl/Native.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/vulkan/Native.hpp"

#include <gtest/gtest.h>

namespace penumbra {
namespace {

std::unique_ptr<rhi::Device> strictDevice(const char* configuration)
{
    rhi::DeviceDesc desc = penumbra::parseConfiguration(configuration);
    desc.validation = true;
    desc.throwOnDebugMessage = true;
    return createDevice(desc);
}

void expectRaisedAtSubmit(rhi::Device& device, rhi::CommandList& commands, const std::string& source)
{
    ASSERT_FALSE(device.debugMessages().empty()) << "the misuse was not reported";
    try {
        device.submit(commands);
        FAIL() << "submit did not raise the debug message";
    } catch (const rhi::Error& e) {
        EXPECT_NE(std::string(e.what()).find(source), std::string::npos) << e.what();
    }
    device.clearDebugMessages();
    EXPECT_TRUE(device.debugMessages().empty());
}

TEST(DebugMessagesTest, VulkanValidationLayerReportsMisuse)
{
    auto device = strictDevice("vulkan");
    auto commands = device->createCommandList();
    // Wide lines are a feature the device did not enable: VUID-vkCmdSetLineWidth-lineWidth-00788.
    vkCmdSetLineWidth(vulkan::native(*commands), 4.0f);
    expectRaisedAtSubmit(*device, *commands, "Vulkan validation");
}

TEST(DebugMessagesTest, OpenGlDebugOutputReportsMisuse)
{
    auto device = strictDevice("opengl");
    opengl::makeCurrent(*device);
    // A name glGenBuffers never returned: GL_INVALID_OPERATION in a core profile.
    opengl::glFunctions(*device).BindBuffer(GL_ARRAY_BUFFER, 123456);
    auto commands = device->createCommandList();
    expectRaisedAtSubmit(*device, *commands, "OpenGL debug output");
}

} // namespace
} // namespace penumbra
