#pragma once

#include "penumbra/rhi/Image.hpp"
#include "penumbra/rhi/LiveObjects.hpp"

#include <cstdint>

// GLFW's window type, opaque here: only the backends include GLFW.
struct GLFWwindow;

namespace penumbra::rhi {

class Texture;

// A window a device presents to. The caller creates it with GLFW after
// penumbra::prepareWindowHints(desc) (backends/) and keeps it alive longer than the device:
// OpenGL makes its context on this window, Vulkan a surface and a swapchain for it.
struct WindowDesc {
    GLFWwindow* glfwWindow = nullptr;
};

// A size in pixels.
struct Extent {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
};

// Shows finished pictures in the device's window. The picture is an RHI texture laid out as
// every render target is (row 0 at the top), so presenting needs no flip from the caller: the
// backend puts row 0 at the top of the window, whatever its API's window origin is.
class Swapchain : private LiveObject<ObjectKind::Swapchain> {
public:
    virtual ~Swapchain() = default;

    // The window's drawable size in pixels now; it follows resizes and is 0 x 0 while minimised.
    virtual Extent drawableSize() const = 0;

    // Acquires the next window image, copies `image` into it (scaled to the window when the sizes
    // differ), presents it and waits until that is done. A resized or out-of-date swapchain is
    // rebuilt here; a minimised window skips the frame.
    void present(const Texture& image)
    {
        if (!minimised())
            show(image, nullptr);
    }

    // present(), and the window's picture as presented, read back from the swapchain image
    // (Vulkan) or the default framebuffer (OpenGL): RGBA8, row 0 at the top, alpha 255. For
    // screenshots and tests; empty (0 x 0) when the frame was skipped.
    Image presentAndReadBack(const Texture& image)
    {
        Image window;
        if (!minimised())
            show(image, &window);
        return window;
    }

protected:
    // Presents `image` to a window of non-zero size; with `window`, also reads the picture back.
    virtual void show(const Texture& image, Image* window) = 0;

private:
    bool minimised() const
    {
        const Extent size = drawableSize();
        return size.width == 0 || size.height == 0;
    }
};

} // namespace penumbra::rhi
