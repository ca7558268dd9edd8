#pragma once

#include "VulkanHandle.hpp"

#include "penumbra/rhi/DebugMessageLog.hpp"

#include <cstdint>
#include <string>
#include <vector>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

// The VkInstance and, with validation, the Khronos layer and a messenger that fills a DebugLog.
class Instance {
public:
    // `extensions`: instance extensions needed besides debug utils (a window surface's).
    Instance(bool validation, rhi::DebugMessageLog& log, std::vector<const char*> extensions);

    VkInstance handle() const { return instance_.get(); }
    // The version the instance was created with: the loader's, capped at 1.3.
    std::uint32_t apiVersion() const { return apiVersion_; }

private:
    UniqueInstance instance_;
    UniqueMessenger messenger_; // after instance_: destroyed before it
    std::uint32_t apiVersion_ = VK_API_VERSION_1_1;
};

struct PhysicalDeviceChoice {
    VkPhysicalDevice device = VK_NULL_HANDLE;
    std::uint32_t queueFamily = 0;
};

// lavapipe by default, else the first Vulkan 1.1 device with a graphics queue;
// PENUMBRA_VULKAN_DEVICE=<part of the name> picks another.
PhysicalDeviceChoice choosePhysicalDevice(VkInstance instance);

} // namespace penumbra::vulkan
