#pragma once

#include "penumbra/vulkan/Native.hpp"

namespace penumbra::apps {

// Throws rhi::Error naming the call when a raw Vulkan call of a benchmark fails.
void checkVulkan(VkResult result, const char* call);

// What every raw Vulkan frame of the benchmarks records into and waits for: one resettable command buffer and a fence.
class RawVulkanCommands {
public:
    explicit RawVulkanCommands(const vulkan::NativeDevice& device);
    ~RawVulkanCommands();
    RawVulkanCommands(const RawVulkanCommands&) = delete;
    RawVulkanCommands& operator=(const RawVulkanCommands&) = delete;

    // Begins the command buffer for one submit.
    VkCommandBuffer begin();
    // Ends, submits and waits for the command buffer, and resets it.
    void submitAndWait();

private:
    vulkan::NativeDevice device_;
    VkCommandPool commandPool_ = VK_NULL_HANDLE;
    VkCommandBuffer commandBuffer_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
};

// One descriptor set of a pipeline's set layout, from a pool of its own, with one buffer at binding 0.
class RawVulkanDescriptorSet {
public:
    RawVulkanDescriptorSet(VkDevice device, VkDescriptorSetLayout layout, VkDescriptorType type, VkBuffer buffer,
                           VkDeviceSize range);
    ~RawVulkanDescriptorSet();
    RawVulkanDescriptorSet(const RawVulkanDescriptorSet&) = delete;
    RawVulkanDescriptorSet& operator=(const RawVulkanDescriptorSet&) = delete;

    VkDescriptorSet set() const { return set_; }

private:
    VkDevice device_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

} // namespace penumbra::apps
