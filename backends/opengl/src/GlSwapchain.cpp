#include "GlSwapchain.hpp"

// GL comes from our own loader (GlFunctions), not from the header GLFW would include.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <algorithm>

namespace penumbra::opengl {

GlSwapchain::GlSwapchain(GlContextPtr context, GLFWwindow* window) : context_(std::move(context)), window_(window)
{
    if (!window_)
        throw rhi::Error("createSwapchain: the device was created without DeviceDesc::window");
}

rhi::Extent GlSwapchain::drawableSize() const
{
    int width = 0;
    int height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return {std::uint32_t(std::max(width, 0)), std::uint32_t(std::max(height, 0))};
}

void GlSwapchain::present(const rhi::Texture& image)
{
    const GlTexture& source = glObject<const GlTexture>(image, "present: the image");
    const rhi::Extent size = drawableSize();
    if (size.width == 0 || size.height == 0)
        return;
    context_->makeCurrent();
    const GlFunctions& gl = context_->gl();
    GLuint read = 0;
    gl.CreateFramebuffers(1, &read);
    if (source.isArray())
        gl.NamedFramebufferTextureLayer(read, GL_COLOR_ATTACHMENT0, source.name(), 0, 0);
    else
        gl.NamedFramebufferTexture(read, GL_COLOR_ATTACHMENT0, source.name(), 0);
    gl.NamedFramebufferReadBuffer(read, GL_COLOR_ATTACHMENT0);
    // The scissor test is the one fragment operation that applies to blits; the next submit
    // sets all state again.
    gl.Disable(GL_SCISSOR_TEST);
    const auto width = GLint(source.desc().width);
    const auto height = GLint(source.desc().height);
    gl.BlitNamedFramebuffer(read, 0, 0, 0, width, height, 0, GLint(size.height), GLint(size.width), 0,
                            GL_COLOR_BUFFER_BIT, GL_NEAREST);
    gl.DeleteFramebuffers(1, &read);
    glfwSwapBuffers(window_);
}

} // namespace penumbra::opengl
