#pragma once

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

// Validation messages as the debug messenger delivers them (from any driver thread).
class DebugLog {
public:
    void add(std::string message);
    std::vector<std::string> all() const;
    // Messages added since the previous call: what submit() raises with throwOnDebugMessage.
    std::vector<std::string> takeUnreported();
    void clear();

private:
    mutable std::mutex mutex_;
    std::vector<std::string> messages_;
    std::size_t reported_ = 0;
};

// The VkInstance and, with validation, the Khronos layer and a messenger that fills a DebugLog.
class Instance {
public:
    Instance(bool validation, DebugLog& log);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    VkInstance handle() const { return instance_; }
    // The version the instance was created with: the loader's, capped at 1.3.
    std::uint32_t apiVersion() const { return apiVersion_; }

private:
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
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
