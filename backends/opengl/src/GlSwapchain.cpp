#include "GlSwapchain.hpp"

// GL comes from our own loader (GlFunctions), not from the header GLFW would include.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <algorithm>

namespace penumbra::opengl {
namespace {

// glReadPixels returns the window's bottom row first; the RHI's pictures start at the top.
rhi::Image readBackBuffer(const GlFunctions& gl, rhi::Extent size)
{
    const std::size_t row = std::size_t(size.width) * 4;
    std::vector<std::byte> bottomUp(row * size.height);
    gl.NamedFramebufferReadBuffer(0, GL_BACK);
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    gl.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, GLsizei(size.width), GLsizei(size.height), GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    rhi::Image picture{size.width, size.height, rhi::Format::RGBA8, std::vector<std::byte>(bottomUp.size())};
    for (std::uint32_t y = 0; y < size.height; ++y)
        std::copy_n(bottomUp.begin() + std::ptrdiff_t(row * (size.height - 1 - y)), row,
                    picture.bytes.begin() + std::ptrdiff_t(row * y));
    for (std::size_t i = 3; i < picture.bytes.size(); i += 4)
        picture.bytes[i] = std::byte{255}; // the window is opaque; its alpha bits, if any, mean nothing
    return picture;
}

} // namespace

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

void GlSwapchain::show(const rhi::Texture& image, rhi::Image* window)
{
    const GlTexture& source = glObject<const GlTexture>(image, "present: the image");
    const rhi::Extent size = drawableSize();
    context_->makeCurrent();
    const GlFunctions& gl = context_->gl();
    const GlFramebufferName readFramebuffer = createName<GlFramebufferName>(*context_, gl.CreateFramebuffers);
    const GLuint read = readFramebuffer.get();
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
    if (window)
        *window = readBackBuffer(gl, size);
    glfwSwapBuffers(window_);
}

} // namespace penumbra::opengl
