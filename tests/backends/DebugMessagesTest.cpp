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

// Labels reach the callbacks: a message names the labels open where the misuse happened (Vulkan: the layer's
// pCmdBufLabels of the command buffer; GL: the application's debug groups as the debug output reports them).
TEST(DebugMessagesTest, VulkanMessagesNameTheOpenLabels)
{
    auto device = strictDevice("vulkan");
    auto commands = device->createCommandList();
    commands->pushLabel("shadows");
    commands->insertLabel("casters");
    commands->pushLabel("cascade 0");
    vkCmdSetLineWidth(vulkan::native(*commands), 4.0f);
    commands->popLabel();
    commands->popLabel();
    const std::vector<std::string> messages = device->debugMessages();
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_NE(messages.front().find("[labels: shadows > cascade 0]"), std::string::npos) << messages.front();
    expectRaisedAtSubmit(*device, *commands, "Vulkan validation");
}

TEST(DebugMessagesTest, OpenGlMessagesNameTheOpenLabels)
{
    auto device = strictDevice("opengl");
    opengl::makeCurrent(*device);
    const opengl::GlFunctions& gl = opengl::glFunctions(*device);
    // What a replayed pushLabel calls, and a misuse inside the group.
    gl.PushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "shadows");
    gl.BindBuffer(GL_ARRAY_BUFFER, 123456);
    gl.PopDebugGroup();
    const std::vector<std::string> messages = device->debugMessages();
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_NE(messages.front().find("[labels: shadows]"), std::string::npos) << messages.front();
    device->clearDebugMessages();
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
