#pragma once

#include "GlResources.hpp"

#include "penumbra/rhi/Window.hpp"

namespace penumbra::opengl {

// The default framebuffer of the GLFW window whose context the device uses. GL's window origin
// is the lower left and cannot be changed, so present() blits the picture upside down into it:
// the RHI's row 0 (the top) lands on the window's top row.
class GlSwapchain final : public rhi::Swapchain {
public:
    GlSwapchain(GlContextPtr context, GLFWwindow* window);

    rhi::Extent drawableSize() const override;

protected:
    void show(const rhi::Texture& image, rhi::Image* window) override;

private:
    GlContextPtr context_;
    GLFWwindow* window_;
};

} // namespace penumbra::opengl
