#include "VulkanSwapchain.hpp"

#include "VulkanCheck.hpp"
#include "VulkanResources.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <optional>
// GLFW's Vulkan functions (glfwCreateWindowSurface) are declared only with this set.
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

namespace penumbra::vulkan {
namespace {

// UNORM: the pictures are already sRGB-encoded (the lit shader writes display values), so the
// window must show their bytes as they are.
VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice device, VkSurfaceKHR surface)
{
    std::uint32_t count = 0;
    check(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, nullptr),
          "vkGetPhysicalDeviceSurfaceFormatsKHR");
    std::vector<VkSurfaceFormatKHR> formats(count);
    check(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, formats.data()),
          "vkGetPhysicalDeviceSurfaceFormatsKHR");
    for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
        for (const VkSurfaceFormatKHR& f : formats)
            if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
                return f;
    throw rhi::Error("Vulkan: the window surface offers neither B8G8R8A8_UNORM nor R8G8B8A8_UNORM");
}

void transitionSwapchainImage(VkCommandBuffer commandBuffer, VkImage image, VkImageLayout from, VkImageLayout to)
{
    transitionImage(commandBuffer, image, {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}, from, to);
}

// Swapchain rows are top first already; BGRA images get their red and blue swapped back.
rhi::Image windowPicture(const std::byte* texels, VkExtent2D extent, bool bgra)
{
    rhi::Image picture{extent.width, extent.height, rhi::Format::RGBA8,
                       std::vector<std::byte>(texels, texels + std::size_t(extent.width) * extent.height * 4)};
    for (std::size_t i = 0; i < picture.bytes.size(); i += 4) {
        if (bgra)
            std::swap(picture.bytes[i], picture.bytes[i + 2]);
        picture.bytes[i + 3] = std::byte{255}; // the window is opaque (VK_COMPOSITE_ALPHA_OPAQUE)
    }
    return picture;
}

} // namespace

std::vector<const char*> windowInstanceExtensions()
{
    if (!glfwVulkanSupported())
        throw rhi::Error("Vulkan: GLFW finds no Vulkan loader (libvulkan1)");
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names)
        throw rhi::Error("Vulkan: no driver offers surface extensions for this window system (no Vulkan driver "
                         "found? install mesa-vulkan-drivers for lavapipe)");
    return {names, names + count};
}

VulkanSwapchain::VulkanSwapchain(std::shared_ptr<Context> context)
    : context_(std::move(context)), window_(context_->desc.window.glfwWindow)
{
    if (!window_)
        throw rhi::Error("createSwapchain: the device was created without DeviceDesc::window");
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    check(glfwCreateWindowSurface(context_->instance.handle(), window_, nullptr, &surface), "glfwCreateWindowSurface");
    surface_ = UniqueSurface(context_->instance.handle(), surface);
    VkBool32 supported = VK_FALSE;
    check(vkGetPhysicalDeviceSurfaceSupportKHR(context_->physicalDevice, context_->queueFamily, surface, &supported),
          "vkGetPhysicalDeviceSurfaceSupportKHR");
    if (!supported)
        throw rhi::Error(fmt::format("Vulkan: {} cannot present to this window from its graphics queue",
                                     context_->capabilities.device));
    const VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    acquired_ = createOwned<UniqueFence>(context_->device, vkCreateFence, fenceInfo, "vkCreateFence");
    rebuild();
}

// The members then destroy the fence, the swapchain and the surface, in that order.
VulkanSwapchain::~VulkanSwapchain() { vkDeviceWaitIdle(context_->device); }

void VulkanSwapchain::destroySwapchain()
{
    if (swapchain_.get())
        vkQueueWaitIdle(context_->queue); // its images may still be on their way to the screen
    swapchain_.reset();
    images_.clear();
}

rhi::Extent VulkanSwapchain::drawableSize() const
{
    int width = 0;
    int height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return {std::uint32_t(std::max(width, 0)), std::uint32_t(std::max(height, 0))};
}

bool VulkanSwapchain::rebuild()
{
    VkSurfaceCapabilitiesKHR caps;
    check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_->physicalDevice, surface_.get(), &caps),
          "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    const rhi::Extent size = drawableSize();
    // currentExtent is the window's size where the platform fixes it (X11), else 0xFFFFFFFF.
    extent_ = caps.currentExtent.width != 0xFFFFFFFFu
                  ? caps.currentExtent
                  : VkExtent2D{std::clamp(size.width, caps.minImageExtent.width, caps.maxImageExtent.width),
                               std::clamp(size.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
    if (extent_.width == 0 || extent_.height == 0)
        return false;
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw rhi::Error("Vulkan: the window's images cannot be copied into (no TRANSFER_DST usage)");
    const VkSurfaceFormatKHR format = chooseFormat(context_->physicalDevice, surface_.get());
    format_ = format.format;
    readable_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
    if (!(context_->formatFeatures(format.format) & VK_FORMAT_FEATURE_BLIT_DST_BIT))
        throw rhi::Error("Vulkan: the window's image format cannot be blitted into");

    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface_.get();
    info.minImageCount =
        caps.maxImageCount == 0 ? caps.minImageCount + 1 : std::min(caps.minImageCount + 1, caps.maxImageCount);
    info.imageFormat = format.format;
    info.imageColorSpace = format.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | (readable_ ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR; // the one mode every driver offers
    info.clipped = VK_TRUE;
    info.oldSwapchain = swapchain_.get();
    UniqueSwapchain created =
        createOwned<UniqueSwapchain>(context_->device, vkCreateSwapchainKHR, info, "vkCreateSwapchainKHR");
    destroySwapchain();
    swapchain_ = std::move(created);
    std::uint32_t count = 0;
    check(vkGetSwapchainImagesKHR(context_->device, swapchain_.get(), &count, nullptr), "vkGetSwapchainImagesKHR");
    images_.resize(count);
    check(vkGetSwapchainImagesKHR(context_->device, swapchain_.get(), &count, images_.data()),
          "vkGetSwapchainImagesKHR");
    return true;
}

void VulkanSwapchain::show(const rhi::Texture& image, rhi::Image* window)
{
    const VulkanTexture& source = vulkanObject<const VulkanTexture>(image, "present: the image");
    const rhi::Extent size = drawableSize();
    if (!swapchain_.get() || size.width != extent_.width || size.height != extent_.height) {
        if (!rebuild())
            return;
    }

    std::uint32_t index = 0;
    const VkResult acquired =
        vkAcquireNextImageKHR(context_->device, swapchain_.get(), UINT64_MAX, VK_NULL_HANDLE, acquired_.get(), &index);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        destroySwapchain(); // rebuilt at the next present
        return;
    }
    if (acquired != VK_SUBOPTIMAL_KHR)
        check(acquired, "vkAcquireNextImageKHR");
    check(vkWaitForFences(context_->device, 1, acquired_.address(), VK_TRUE, UINT64_MAX), "vkWaitForFences");
    check(vkResetFences(context_->device, 1, acquired_.address()), "vkResetFences");

    if (window && !readable_)
        throw rhi::Error("Vulkan: the window's images cannot be read back (no TRANSFER_SRC usage)");
    const VkImage target = images_[index];
    const rhi::TextureDesc& desc = source.desc();
    const VkDeviceSize readbackSize = VkDeviceSize(extent_.width) * extent_.height * 4;
    std::optional<MappedBuffer> readback;
    if (window)
        readback.emplace(context_, readbackSize, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    context_->runOnce([&](VkCommandBuffer commandBuffer) {
        source.transition(commandBuffer, 0, source.restingLayout(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        transitionSwapchainImage(commandBuffer, target, VK_IMAGE_LAYOUT_UNDEFINED,
                                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        // Both images keep row 0 at the top (the RHI's layout, and what a swapchain shows first), so
        // the blit copies rows straight; it converts RGBA to the window's BGRA and scales if needed.
        VkImageBlit region{};
        region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.srcOffsets[1] = {std::int32_t(desc.width), std::int32_t(desc.height), 1};
        region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.dstOffsets[1] = {std::int32_t(extent_.width), std::int32_t(extent_.height), 1};
        vkCmdBlitImage(commandBuffer, source.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
        source.transition(commandBuffer, 0, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, source.restingLayout());
        VkImageLayout layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        if (readback) {
            transitionSwapchainImage(commandBuffer, target, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
            layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
            VkBufferImageCopy copy{};
            copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            copy.imageExtent = {extent_.width, extent_.height, 1};
            vkCmdCopyImageToBuffer(commandBuffer, target, layout, readback->handle(), 1, &copy);
            fullBarrier(commandBuffer);
        }
        transitionSwapchainImage(commandBuffer, target, layout, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
    });
    if (window)
        *window = windowPicture(readback->data(), extent_, format_ == VK_FORMAT_B8G8R8A8_UNORM);

    VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    info.swapchainCount = 1;
    info.pSwapchains = swapchain_.address();
    info.pImageIndices = &index;
    const VkResult presented = vkQueuePresentKHR(context_->queue, &info);
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR)
        destroySwapchain();
    else
        check(presented, "vkQueuePresentKHR");
}

} // namespace penumbra::vulkan
