// OpenGLDeviceOptions::context: both headless context providers give the same pixels.
#include "GpuTesting.hpp"
#include "TestPattern.hpp"

#include "penumbra/opengl/OpenGLDevice.hpp"
#include "penumbra/rhi/Error.hpp"

#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

TEST(OpenGLContextTest, OsMesaAndEglContextsAgree)
{
    const rhi::DeviceDesc desc = penumbra::parseConfiguration("opengl");
    std::vector<rhi::Image> images;
    for (opengl::ContextProvider provider :
         {opengl::ContextProvider::EglSurfaceless, opengl::ContextProvider::OSMesa}) {
        std::unique_ptr<rhi::Device> device;
        try {
            device = opengl::createOpenGLDevice(desc, {.context = provider});
        } catch (const rhi::UnsupportedError& e) {
            GTEST_SKIP() << e.what();
        }
        pattern::PatternRenderer renderer(*device, {.width = 128, .height = 128});
        renderer.render(pattern::testPattern());
        images.push_back(renderer.color());
        expectNoDebugMessages(*device);
    }
    ASSERT_EQ(images[0].bytes.size(), images[1].bytes.size());
    EXPECT_TRUE(images[0].bytes == images[1].bytes) << "EGL and OSMesa patterns differ";
}

} // namespace
} // namespace penumbra::testing
