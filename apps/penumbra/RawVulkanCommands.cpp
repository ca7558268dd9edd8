#include "RawVulkanCommands.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::apps {

void checkVulkan(VkResult result, const char* call)
{
    if (result != VK_SUCCESS)
        throw rhi::Error(fmt::format("raw Vulkan benchmark: {} failed ({})", call, int(result)));
}

RawVulkanCommands::RawVulkanCommands(const vulkan::NativeDevice& device) : device_(device)
{
    const VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO, nullptr,
                                           VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT, device_.queueFamilyIndex};
    checkVulkan(vkCreateCommandPool(device_.device, &poolInfo, nullptr, &commandPool_), "vkCreateCommandPool");
    const VkCommandBufferAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, nullptr,
                                                   commandPool_, VK_COMMAND_BUFFER_LEVEL_PRIMARY, 1};
    checkVulkan(vkAllocateCommandBuffers(device_.device, &allocateInfo, &commandBuffer_), "vkAllocateCommandBuffers");
    const VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO, nullptr, 0};
    checkVulkan(vkCreateFence(device_.device, &fenceInfo, nullptr, &fence_), "vkCreateFence");
}

RawVulkanCommands::~RawVulkanCommands()
{
    vkDestroyFence(device_.device, fence_, nullptr);
    vkDestroyCommandPool(device_.device, commandPool_, nullptr);
}

VkCommandBuffer RawVulkanCommands::begin()
{
    const VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO, nullptr,
                                         VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT, nullptr};
    checkVulkan(vkBeginCommandBuffer(commandBuffer_, &begin), "vkBeginCommandBuffer");
    return commandBuffer_;
}

void RawVulkanCommands::submitAndWait()
{
    checkVulkan(vkEndCommandBuffer(commandBuffer_), "vkEndCommandBuffer");
    const VkSubmitInfo submit{
        VK_STRUCTURE_TYPE_SUBMIT_INFO, nullptr, 0, nullptr, nullptr, 1, &commandBuffer_, 0, nullptr};
    checkVulkan(vkQueueSubmit(device_.queue, 1, &submit, fence_), "vkQueueSubmit");
    checkVulkan(vkWaitForFences(device_.device, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    checkVulkan(vkResetFences(device_.device, 1, &fence_), "vkResetFences");
    checkVulkan(vkResetCommandBuffer(commandBuffer_, 0), "vkResetCommandBuffer");
}

RawVulkanDescriptorSet::RawVulkanDescriptorSet(VkDevice device, VkDescriptorSetLayout layout, VkDescriptorType type,
                                               VkBuffer buffer, VkDeviceSize range)
    : device_(device)
{
    const VkDescriptorPoolSize size{type, 1};
    const VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO, nullptr, 0, 1, 1, &size};
    checkVulkan(vkCreateDescriptorPool(device_, &poolInfo, nullptr, &pool_), "vkCreateDescriptorPool");
    const VkDescriptorSetAllocateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO, nullptr, pool_, 1,
                                              &layout};
    checkVulkan(vkAllocateDescriptorSets(device_, &setInfo, &set_), "vkAllocateDescriptorSets");
    const VkDescriptorBufferInfo bufferInfo{buffer, 0, range};
    const VkWriteDescriptorSet write{
        VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, nullptr, set_, 0, 0, 1, type, nullptr, &bufferInfo, nullptr};
    vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
}

RawVulkanDescriptorSet::~RawVulkanDescriptorSet() { vkDestroyDescriptorPool(device_, pool_, nullptr); }

} // namespace penumbra::apps
