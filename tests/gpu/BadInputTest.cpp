#include "GpuTesting.hpp"

#include "penumbra/rhi/Error.hpp"

namespace penumbra::testing {
namespace {

using BadInputTest = GpuTest;

TEST_F(BadInputTest, GlslErrorNamesFileAndLine)
{
    try {
        device->createShader(
            {rhi::ShaderStage::Fragment, "#version 450\n\nvoid main() { missing(); }\n", "broken.frag"});
        FAIL() << "a broken shader was accepted";
    } catch (const rhi::ShaderCompileError& e) {
        EXPECT_NE(std::string(e.what()).find("broken.frag:3"), std::string::npos) << e.what();
    }
}

TEST_F(BadInputTest, MismatchedFramebufferSizesAreRefused)
{
    auto a =
        device->createTexture({.width = 8, .height = 8, .usage = rhi::TextureUsage::RenderTarget, .debugName = "a"});
    auto b = device->createTexture({.width = 4,
                                    .height = 8,
                                    .format = rhi::Format::D32F,
                                    .usage = rhi::TextureUsage::RenderTarget,
                                    .debugName = "b"});
    const rhi::Attachment color{a.get(), 0};
    EXPECT_THROW(device->createFramebuffer({.colors = {&color, 1}, .depth = {b.get(), 0}}), rhi::Error);
}

TEST_F(BadInputTest, LayerOutOfRangeIsRefused)
{
    auto t = device->createTexture({.width = 8, .height = 8, .layers = 2, .usage = rhi::TextureUsage::RenderTarget});
    const rhi::Attachment color{t.get(), 2};
    EXPECT_THROW(device->createFramebuffer({.colors = {&color, 1}}), rhi::Error);
}

} // namespace
} // namespace penumbra::testing
