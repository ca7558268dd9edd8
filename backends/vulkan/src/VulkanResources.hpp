#pragma once

#include "VulkanContext.hpp"

#include "penumbra/rhi/Resources.hpp"

#include <memory>
#include <vector>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

// A VkBuffer in host-visible, coherent memory, mapped for its whole life.
class MappedBuffer {
public:
    MappedBuffer(std::shared_ptr<Context> context, VkDeviceSize size, VkBufferUsageFlags usage);

    VkBuffer handle() const { return buffer_.get(); }
    std::byte* data() const { return mapped_; }

private:
    std::shared_ptr<Context> context_;
    UniqueBuffer buffer_;
    UniqueMemory memory_;
    std::byte* mapped_ = nullptr;
};

class VulkanBuffer final : public rhi::Buffer {
public:
    VulkanBuffer(std::shared_ptr<Context> context, const rhi::BufferDesc& desc);

    const rhi::BufferDesc& desc() const override { return desc_; }
    void write(std::uint64_t offset, std::span<const std::byte> data) override;
    void read(std::uint64_t offset, std::span<std::byte> data) const override;

    VkBuffer handle() const { return buffer_.handle(); }

private:
    rhi::BufferDesc desc_;
    MappedBuffer buffer_;
};

// Moves `range` of `image` between layouts, waiting for all earlier work (the backend's simple,
// always-correct synchronisation; see fullBarrier).
void transitionImage(VkCommandBuffer commandBuffer, VkImage image, const VkImageSubresourceRange& range,
                     VkImageLayout from, VkImageLayout to);

// A 2D (array) or cube-array image; attachments and copies address single layers either way.
// Between commands it rests in restingLayout(): shader-read if it can be sampled, else its
// attachment layout; passes and copies start and end there.
class VulkanTexture final : public rhi::Texture {
public:
    VulkanTexture(std::shared_ptr<Context> context, const rhi::TextureDesc& desc);

    const rhi::TextureDesc& desc() const override { return desc_; }

    VkImage image() const { return image_.get(); }
    // The view shaders sample: every layer (2D, 2D array or cube array) and level, depth aspect only for D24S8.
    VkImageView sampledView() const { return view_.get(); }
    // One mip level as a storage image (TextureUsage::Storage).
    VkImageView storageView(std::uint32_t level) const { return storageViews_[level].get(); }
    VkFormat format() const { return format_; }
    VkImageLayout restingLayout() const { return restingLayout_; }
    // Level 0 of one layer with every aspect, for a framebuffer.
    UniqueImageView createAttachmentView(std::uint32_t layer) const;
    // Moves every level of one layer (or of all with layer = ~0u) between layouts, waiting for all earlier work.
    void transition(VkCommandBuffer commandBuffer, std::uint32_t layer, VkImageLayout from, VkImageLayout to) const;
    // Copies `data` into one level of one layer through `staging` (at least data.size() bytes), and waits.
    void upload(std::uint32_t layer, std::uint32_t level, std::span<const std::byte> data, MappedBuffer& staging);

private:
    std::shared_ptr<Context> context_;
    rhi::TextureDesc desc_;
    VkFormat format_;
    VkImageLayout restingLayout_;
    // Destroyed in reverse order: the view first, the memory last.
    UniqueMemory memory_;
    UniqueImage image_;
    UniqueImageView view_;
    std::vector<UniqueImageView> storageViews_;
};

class VulkanSampler final : public rhi::Sampler {
public:
    VulkanSampler(std::shared_ptr<Context> context, const rhi::SamplerDesc& desc);

    const rhi::SamplerDesc& desc() const override { return desc_; }
    VkSampler handle() const { return sampler_.get(); }

private:
    std::shared_ptr<Context> context_;
    rhi::SamplerDesc desc_;
    UniqueSampler sampler_;
};

class VulkanTimestampQueries final : public rhi::TimestampQueries {
public:
    VulkanTimestampQueries(std::shared_ptr<Context> context, std::uint32_t count);

    std::uint32_t count() const override { return count_; }
    VkQueryPool handle() const { return pool_.get(); }
    std::vector<double> readNanoseconds() const;

private:
    std::shared_ptr<Context> context_;
    std::uint32_t count_;
    UniqueQueryPool pool_;
};

} // namespace penumbra::vulkan
