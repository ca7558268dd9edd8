#pragma once

// Owning handles for Vulkan objects. Each destroys its object exactly once, when it goes out of
// scope, so a constructor that throws half-way releases whatever it had already created: members
// that are fully constructed are destroyed even when the enclosing constructor fails (C++ Core
// Guidelines R.1 "Manage resources automatically using resource handles and RAII", E.6).

#include "VulkanCheck.hpp"

#include <string_view>
#include <utility>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

// An object of `Parent` (a VkDevice or VkInstance), destroyed with `destroy(parent, handle, nullptr)`.
template <typename Parent, typename T, void (*destroy)(Parent, T, const VkAllocationCallbacks*)>
class Owned {
public:
    Owned() = default;
    Owned(Parent parent, T handle) : parent_(parent), handle_(handle) {}
    ~Owned() { reset(); }
    Owned(Owned&& other) noexcept : parent_(other.parent_), handle_(std::exchange(other.handle_, VK_NULL_HANDLE)) {}
    Owned& operator=(Owned&& other) noexcept
    {
        if (this != &other) {
            reset();
            parent_ = other.parent_;
            handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
        }
        return *this;
    }

    T get() const { return handle_; }
    const T* address() const { return &handle_; }
    void reset()
    {
        if (handle_ != VK_NULL_HANDLE)
            destroy(parent_, std::exchange(handle_, VK_NULL_HANDLE), nullptr);
    }

private:
    Parent parent_ = VK_NULL_HANDLE;
    T handle_ = VK_NULL_HANDLE;
};

template <typename T, void (*destroy)(VkDevice, T, const VkAllocationCallbacks*)>
using DeviceOwned = Owned<VkDevice, T, destroy>;

using UniqueBuffer = DeviceOwned<VkBuffer, vkDestroyBuffer>;
using UniqueCommandPool = DeviceOwned<VkCommandPool, vkDestroyCommandPool>;
using UniqueDescriptorPool = DeviceOwned<VkDescriptorPool, vkDestroyDescriptorPool>;
using UniqueDescriptorSetLayout = DeviceOwned<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using UniqueFence = DeviceOwned<VkFence, vkDestroyFence>;
using UniqueFramebuffer = DeviceOwned<VkFramebuffer, vkDestroyFramebuffer>;
using UniqueImage = DeviceOwned<VkImage, vkDestroyImage>;
using UniqueImageView = DeviceOwned<VkImageView, vkDestroyImageView>;
using UniqueMemory = DeviceOwned<VkDeviceMemory, vkFreeMemory>; // freeing unmaps implicitly
using UniquePipeline = DeviceOwned<VkPipeline, vkDestroyPipeline>;
using UniquePipelineCache = DeviceOwned<VkPipelineCache, vkDestroyPipelineCache>;
using UniquePipelineLayout = DeviceOwned<VkPipelineLayout, vkDestroyPipelineLayout>;
using UniqueQueryPool = DeviceOwned<VkQueryPool, vkDestroyQueryPool>;
using UniqueRenderPass = DeviceOwned<VkRenderPass, vkDestroyRenderPass>;
using UniqueSampler = DeviceOwned<VkSampler, vkDestroySampler>;
using UniqueSemaphore = DeviceOwned<VkSemaphore, vkDestroySemaphore>;
using UniqueShaderModule = DeviceOwned<VkShaderModule, vkDestroyShaderModule>;
using UniqueSurface = Owned<VkInstance, VkSurfaceKHR, vkDestroySurfaceKHR>;
using UniqueSwapchain = DeviceOwned<VkSwapchainKHR, vkDestroySwapchainKHR>;

// A handle without a parent, destroyed with `destroy(handle, nullptr)`: the VkInstance and the VkDevice.
template <typename T, void (*destroy)(T, const VkAllocationCallbacks*)>
class Root {
public:
    Root() = default;
    explicit Root(T handle) : handle_(handle) {}
    ~Root()
    {
        if (handle_ != VK_NULL_HANDLE)
            destroy(handle_, nullptr);
    }
    Root(Root&& other) noexcept : handle_(std::exchange(other.handle_, VK_NULL_HANDLE)) {}
    Root& operator=(Root&& other) noexcept
    {
        std::swap(handle_, other.handle_);
        return *this;
    }

    T get() const { return handle_; }

private:
    T handle_ = VK_NULL_HANDLE;
};

using UniqueInstance = Root<VkInstance, vkDestroyInstance>;
using UniqueDevice = Root<VkDevice, vkDestroyDevice>;

// The debug messenger: its destroy function is an extension entry point, looked up at run time.
class UniqueMessenger {
public:
    UniqueMessenger() = default;
    UniqueMessenger(VkInstance instance, VkDebugUtilsMessengerEXT messenger,
                    PFN_vkDestroyDebugUtilsMessengerEXT destroy)
        : instance_(instance), messenger_(messenger), destroy_(destroy)
    {
    }
    ~UniqueMessenger()
    {
        if (messenger_ != VK_NULL_HANDLE)
            destroy_(instance_, messenger_, nullptr);
    }
    UniqueMessenger(const UniqueMessenger&) = delete;
    UniqueMessenger& operator=(UniqueMessenger&& other) noexcept
    {
        std::swap(instance_, other.instance_);
        std::swap(messenger_, other.messenger_);
        std::swap(destroy_, other.destroy_);
        return *this;
    }

private:
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    PFN_vkDestroyDebugUtilsMessengerEXT destroy_ = nullptr;
};

// Creates a device object with the usual vkCreateX(device, info, allocator, out) signature (and
// vkAllocateMemory's, which has it too); a failure throws rhi::Error naming `call`.
template <typename Unique, typename Info, typename Handle>
Unique createOwned(VkDevice device, VkResult (*create)(VkDevice, const Info*, const VkAllocationCallbacks*, Handle*),
                   const Info& info, std::string_view call)
{
    Handle handle = VK_NULL_HANDLE;
    check(create(device, &info, nullptr, &handle), call);
    return Unique(device, handle);
}

} // namespace penumbra::vulkan
