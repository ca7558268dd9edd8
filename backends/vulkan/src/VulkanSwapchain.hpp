#pragma once

#include "VulkanContext.hpp"

#include "penumbra/rhi/Window.hpp"

#include <memory>
#include <vector>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

// The instance extensions a GLFW window's surface needs (VK_KHR_surface and the platform's);
// throws rhi::Error when GLFW finds no Vulkan loader or no presentation support.
std::vector<const char*> windowInstanceExtensions();

// A VkSurfaceKHR on the device's GLFW window and a VkSwapchainKHR for it. Each present acquires an
// image (waiting on a fence, so no semaphore is needed), blits the picture into it, waits for
// that, and presents; the device's submit-and-wait model keeps this free of frame overlap.
class VulkanSwapchain final : public rhi::Swapchain {
public:
    explicit VulkanSwapchain(std::shared_ptr<Context> context);
    ~VulkanSwapchain() override;

    rhi::Extent drawableSize() const override;

protected:
    void show(const rhi::Texture& image, rhi::Image* window) override;

private:
    // (Re)creates the swapchain at the window's current size; false while the window is minimised.
    bool rebuild();
    void destroySwapchain();

    std::shared_ptr<Context> context_;
    GLFWwindow* window_;
    UniqueSurface surface_;
    UniqueSwapchain swapchain_; // after surface_: destroyed before it
    UniqueFence acquired_;
    VkExtent2D extent_{};
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    bool readable_ = false; // the images allow TRANSFER_SRC, so presentAndReadBack works
    std::vector<VkImage> images_;
};

} // namespace penumbra::vulkan
