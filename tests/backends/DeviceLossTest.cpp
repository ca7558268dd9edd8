// A device lost during work is reported as rhi::DeviceLostError with the API's code, never a crash: on Vulkan through
// the device-loss test layer (tests/support/device_loss), which answers VK_ERROR_DEVICE_LOST from a chosen
// submission on; the lost device's objects are destroyed cleanly and a new device works. OpenGL's loss cannot be
// provoked on llvmpipe; its contexts are made to report one (Capabilities::deviceLossReported).
#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/Image.hpp"

#include <cstddef>
#include <cstdlib>
#include <gtest/gtest.h>

namespace penumbra {
namespace {

std::unique_ptr<rhi::Device> throwingDevice(const char* configuration)
{
    rhi::DeviceDesc desc = penumbra::parseConfiguration(configuration);
    desc.validation = true;
    desc.throwOnDebugMessage = true;
    return createDevice(desc);
}

// A 4 x 4 target cleared to `color` and submitted.
struct ClearedTarget {
    std::unique_ptr<rhi::Texture> texture;
    std::unique_ptr<rhi::Framebuffer> framebuffer;
    std::unique_ptr<rhi::CommandList> commands;

    ClearedTarget(rhi::Device& device, glm::vec4 color)
        : texture(device.createTexture({.width = 4, .height = 4, .usage = rhi::TextureUsage::RenderTarget})),
          commands(device.createCommandList())
    {
        const rhi::Attachment attachment{texture.get(), 0};
        framebuffer = device.createFramebuffer({.colors = {&attachment, 1}});
        commands->beginPass({.framebuffer = framebuffer.get(), .clearColor = color});
        commands->endPass();
    }
};

// The loader reads its layer variables when an instance is made, and each device of the Vulkan backend makes its own.
// The layer is implicit, switched on by its variable (the loader warns of layers forced on by VK_INSTANCE_LAYERS,
// which the validation messenger would count as a message), and found through XDG_CONFIG_HOME (this loader, 1.3.239,
// has no VK_ADD_IMPLICIT_LAYER_PATH).
class VulkanDeviceLossTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        setenv("XDG_CONFIG_HOME", PENUMBRA_DEVICE_LOSS_LAYER_PATH, 1); // holds vulkan/implicit_layer.d
        setenv("PENUMBRA_DEVICE_LOSS_LAYER", "1", 1);
    }
    void TearDown() override
    {
        unsetenv("PENUMBRA_DEVICE_LOSS_LAYER");
        unsetenv("XDG_CONFIG_HOME");
        unsetenv("PENUMBRA_LOSE_DEVICE_AT_SUBMIT");
    }
};

TEST_F(VulkanDeviceLossTest, ALostDeviceIsReportedWithTheApiCodeAndANewDeviceWorks)
{
    // Making the device and the target submits too (uploads, layout changes): the loss comes at the test's third
    // submission or before.
    setenv("PENUMBRA_LOSE_DEVICE_AT_SUBMIT", "4", 1);
    {
        auto device = throwingDevice("vulkan");
        ClearedTarget target(*device, glm::vec4(1.0f));
        int succeeded = 0;
        int lost = 0;
        for (int submission = 0; submission < 6; ++submission) {
            try {
                device->submit(*target.commands);
                EXPECT_EQ(lost, 0) << "a submission succeeded after the loss";
                ++succeeded;
            } catch (const rhi::DeviceLostError& e) {
                EXPECT_NE(std::string(e.what()).find("vkQueueSubmit failed: VK_ERROR_DEVICE_LOST"), std::string::npos)
                    << e.what();
                ++lost;
            }
        }
        EXPECT_GT(succeeded, 0);
        EXPECT_GE(lost, 3);
        for (const std::string& message : device->debugMessages())
            ADD_FAILURE() << message;
    } // every object of the lost device destroyed here, without a crash or a validation message

    setenv("PENUMBRA_LOSE_DEVICE_AT_SUBMIT", "0", 1);
    auto device = throwingDevice("vulkan");
    ClearedTarget target(*device, glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
    device->submit(*target.commands);
    const rhi::Image image = rhi::readTexture(*device, *target.texture);
    EXPECT_EQ(std::to_integer<int>(image.bytes[0]), 0);
    EXPECT_EQ(std::to_integer<int>(image.bytes[1]), 255);
    EXPECT_TRUE(device->capabilities().deviceLossReported);
}

// The control: without the layer's loss the same submissions succeed, so the loss above is the layer's.
TEST_F(VulkanDeviceLossTest, WithoutALossEverySubmissionSucceeds)
{
    setenv("PENUMBRA_LOSE_DEVICE_AT_SUBMIT", "0", 1);
    auto device = throwingDevice("vulkan");
    ClearedTarget target(*device, glm::vec4(1.0f));
    for (int submission = 0; submission < 3; ++submission)
        EXPECT_NO_THROW(device->submit(*target.commands));
}

// EGL contexts are made with the lose-context-on-reset strategy where the display offers it, as Mesa's does.
TEST(OpenGlDeviceLossTest, TheContextReportsResets)
{
    auto device = throwingDevice("opengl");
    EXPECT_TRUE(device->capabilities().deviceLossReported);
    ClearedTarget target(*device, glm::vec4(1.0f));
    EXPECT_NO_THROW(device->submit(*target.commands));
}

} // namespace
} // namespace penumbra
