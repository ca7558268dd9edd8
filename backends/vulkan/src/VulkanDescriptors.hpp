#pragma once

#include "VulkanContext.hpp"

#include <vector>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

struct DescriptorLayout;

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

// What a command list has bound to each binding number, and the descriptor set that holds it, for one bind point
// (graphics or compute; a list keeps one binder per bind point, both given every binding).
// A new set is written only when buffers, textures or samplers change; changed uniform offsets
// alone are just new dynamic offsets.
class DescriptorBinder {
public:
    explicit DescriptorBinder(std::shared_ptr<Context> context) : allocator_(std::move(context)) {}

    void setPipeline(const DescriptorLayout& pipeline);
    void setUniformBuffer(std::uint32_t binding, VkBuffer buffer, std::uint32_t offset, VkDeviceSize size);
    void setTexture(std::uint32_t binding, VkImageView view, VkSampler sampler, VkImageLayout layout);
    void setStorageBuffer(std::uint32_t binding, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize size);
    void setStorageImage(std::uint32_t binding, VkImageView view);
    // Before a draw: writes and binds a new set, or rebinds the current one with new offsets, or nothing.
    void flush(VkCommandBuffer commandBuffer)
    {
        if (setDirty_ || offsetsDirty_)
            bind(commandBuffer);
    }
    // Another binder's set took the bind point: the next flush binds this one's set again.
    void rebind()
    {
        if (set_ != VK_NULL_HANDLE)
            offsetsDirty_ = true;
    }
    // After submit: the sets are gone and bound resources may be destroyed.
    void reset();

private:
    struct Bound {
        VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
        VkBuffer buffer = VK_NULL_HANDLE;
        VkDeviceSize size = 0;
        VkDeviceSize storageOffset = 0; // a storage buffer's offset, written into the set
        std::uint32_t offset = 0; // a uniform buffer's dynamic offset
        VkImageView view = VK_NULL_HANDLE;
        VkSampler sampler = VK_NULL_HANDLE;
        VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;

        bool sameDescriptor(const Bound& other) const
        {
            return type == other.type && buffer == other.buffer && size == other.size &&
                   storageOffset == other.storageOffset && view == other.view && sampler == other.sampler &&
                   layout == other.layout;
        }
    };
    void set(std::uint32_t binding, const Bound& bound);

    Bound& slot(std::uint32_t binding);
    void bind(VkCommandBuffer commandBuffer);
    void writeSet();

    DescriptorAllocator allocator_;
    std::vector<Bound> bound_;
    const DescriptorLayout* pipeline_ = nullptr;
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
