#include "GpuTesting.hpp"
#include "TestPattern.hpp"

namespace penumbra::testing {
namespace {

using TimestampTest = GpuTest;

TEST_F(TimestampTest, TimestampsAroundWorkIncrease)
{
    ASSERT_TRUE(device->capabilities().timestamps) << device->capabilities().device;
    auto queries = device->createTimestampQueries(2);
    auto target = device->createTexture(
        {.width = 256, .height = 256, .format = rhi::Format::RGBA8, .usage = rhi::TextureUsage::RenderTarget});
    const rhi::Attachment attachment{target.get(), 0};
    auto framebuffer = device->createFramebuffer({.colors = {&attachment, 1}});
    auto commands = device->createCommandList();
    commands->writeTimestamp(*queries, 0);
    commands->beginPass({.framebuffer = framebuffer.get(), .clearColor = glm::vec4(1, 0, 0, 1)});
    commands->endPass();
    commands->writeTimestamp(*queries, 1);
    device->submit(*commands);
    const std::vector<double> ns = device->readTimestamps(*queries);
    ASSERT_EQ(ns.size(), 2u);
    EXPECT_GE(ns[1], ns[0]);
    EXPECT_GT(ns[0], 0.0);
}

} // namespace
} // namespace penumbra::testing
