#pragma once

#include "VulkanContext.hpp"

#include <vector>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

class VulkanPipeline;

// Descriptor sets for one command list: allocated from a growing list of pools, all reset after submit.
class DescriptorAllocator {
public:
    explicit DescriptorAllocator(std::shared_ptr<Context> context) : context_(std::move(context)) {}

    VkDescriptorSet allocate(VkDescriptorSetLayout layout);
    void reset();
    VkDevice device() const { return context_->device; }

private:
    UniqueDescriptorPool createPool() const;

    std::shared_ptr<Context> context_;
    std::vector<UniqueDescriptorPool> pools_;
    std::size_t current_ = 0;
};

// What a command list has bound to each binding number, and the descriptor set that holds it.
// A new set is written only when buffers, textures or samplers change; changed uniform offsets
// alone are just new dynamic offsets.
class DescriptorBinder {
public:
    explicit DescriptorBinder(std::shared_ptr<Context> context) : allocator_(std::move(context)) {}

    void setPipeline(const VulkanPipeline& pipeline);
    void setUniformBuffer(std::uint32_t binding, VkBuffer buffer, std::uint32_t offset, VkDeviceSize size);
    void setTexture(std::uint32_t binding, VkImageView view, VkSampler sampler);
    // Before a draw: writes and binds a new set, or rebinds the current one with new offsets, or nothing.
    void flush(VkCommandBuffer commandBuffer)
    {
        if (setDirty_ || offsetsDirty_)
            bind(commandBuffer);
    }
    // After submit: the sets are gone and bound resources may be destroyed.
    void reset();

private:
    struct Bound {
        bool isBuffer = false;
        bool isTexture = false;
        VkBuffer buffer = VK_NULL_HANDLE;
        VkDeviceSize size = 0;
        std::uint32_t offset = 0;
        VkImageView view = VK_NULL_HANDLE;
        VkSampler sampler = VK_NULL_HANDLE;
    };

    Bound& slot(std::uint32_t binding);
    void bind(VkCommandBuffer commandBuffer);
    void writeSet();

    DescriptorAllocator allocator_;
    std::vector<Bound> bound_;
    const VulkanPipeline* pipeline_ = nullptr;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    bool setDirty_ = false;
    bool offsetsDirty_ = false;
    std::vector<std::uint32_t> offsets_;
    std::vector<VkDescriptorBufferInfo> bufferInfos_;
    std::vector<VkDescriptorImageInfo> imageInfos_;
    std::vector<VkWriteDescriptorSet> writes_;
};

} // namespace penumbra::vulkan
