#include "VulkanDescriptors.hpp"

#include "VulkanCheck.hpp"
#include "VulkanPipeline.hpp"

#include "penumbra/rhi/Error.hpp"

#include <array>
#include <fmt/format.h>

namespace penumbra::vulkan {
namespace {

constexpr std::uint32_t setsPerPool = 1024;

} // namespace

UniqueDescriptorPool DescriptorAllocator::createPool() const
{
    const std::array<VkDescriptorPoolSize, 4> sizes{{
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, setsPerPool * 4},
        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, setsPerPool * 4},
        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, setsPerPool},
        {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, setsPerPool},
    }};
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.maxSets = setsPerPool;
    info.poolSizeCount = std::uint32_t(sizes.size());
    info.pPoolSizes = sizes.data();
    return createOwned<UniqueDescriptorPool>(context_->device, vkCreateDescriptorPool, info, "vkCreateDescriptorPool");
}

VkDescriptorSet DescriptorAllocator::allocate(VkDescriptorSetLayout layout)
{
    VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    for (;; ++current_) {
        if (current_ == pools_.size())
            pools_.push_back(createPool());
        info.descriptorPool = pools_[current_].get();
        VkDescriptorSet set = VK_NULL_HANDLE;
        const VkResult result = vkAllocateDescriptorSets(context_->device, &info, &set);
        if (result == VK_SUCCESS)
            return set;
        // A full pool: move on to the next one, creating it if needed.
        if (result != VK_ERROR_OUT_OF_POOL_MEMORY && result != VK_ERROR_FRAGMENTED_POOL)
            check(result, "vkAllocateDescriptorSets");
    }
}

void DescriptorAllocator::reset()
{
    for (std::size_t i = 0; i < pools_.size() && i <= current_; ++i)
        check(vkResetDescriptorPool(context_->device, pools_[i].get(), 0), "vkResetDescriptorPool");
    current_ = 0;
}

DescriptorBinder::Bound& DescriptorBinder::slot(std::uint32_t binding)
{
    if (binding >= bound_.size())
        bound_.resize(binding + 1);
    return bound_[binding];
}

void DescriptorBinder::setPipeline(const DescriptorLayout& pipeline)
{
    pipeline_ = &pipeline;
    // Pipelines with the same bindings share a layout (LayoutCache), and then the set stays valid.
    if (pipeline.layout.layout != layout_) {
        layout_ = pipeline.layout.layout;
        setDirty_ = !pipeline.bindings->empty();
        offsetsDirty_ = false;
    }
}

void DescriptorBinder::set(std::uint32_t binding, const Bound& bound)
{
    Bound& b = slot(binding);
    if (!b.sameDescriptor(bound)) {
        b = bound;
        setDirty_ = true;
    }
}

void DescriptorBinder::setUniformBuffer(std::uint32_t binding, VkBuffer buffer, std::uint32_t offset, VkDeviceSize size)
{
    Bound& b = slot(binding);
    if (b.type != VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC || b.buffer != buffer || b.size != size) {
        b = Bound{.type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, .buffer = buffer, .size = size};
        setDirty_ = true;
    }
    if (b.offset != offset) {
        b.offset = offset;
        offsetsDirty_ = true;
    }
}

void DescriptorBinder::setTexture(std::uint32_t binding, VkImageView view, VkSampler sampler, VkImageLayout layout)
{
    set(binding,
        {.type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, .view = view, .sampler = sampler, .layout = layout});
}

void DescriptorBinder::setStorageBuffer(std::uint32_t binding, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize size)
{
    set(binding, {.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, .buffer = buffer, .size = size, .storageOffset = offset});
}

void DescriptorBinder::setStorageImage(std::uint32_t binding, VkImageView view)
{
    set(binding, {.type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, .view = view, .layout = VK_IMAGE_LAYOUT_GENERAL});
}

void DescriptorBinder::reset()
{
    allocator_.reset();
    bound_.clear();
    pipeline_ = nullptr;
    layout_ = VK_NULL_HANDLE;
    set_ = VK_NULL_HANDLE;
    setDirty_ = false;
    offsetsDirty_ = false;
}

void DescriptorBinder::bind(VkCommandBuffer commandBuffer)
{
    if (pipeline_->bindings->empty()) {
        setDirty_ = offsetsDirty_ = false;
        return;
    }
    if (setDirty_)
        writeSet();
    const std::vector<std::uint32_t>& uniforms = pipeline_->uniformBindings;
    offsets_.resize(uniforms.size());
    for (std::size_t i = 0; i < uniforms.size(); ++i)
        offsets_[i] = bound_[uniforms[i]].offset;
    vkCmdBindDescriptorSets(commandBuffer, pipeline_->bindPoint, layout_, 0, 1, &set_, std::uint32_t(offsets_.size()),
                            offsets_.data());
    setDirty_ = false;
    offsetsDirty_ = false;
}

void DescriptorBinder::writeSet()
{
    const std::vector<rhi::ShaderBinding>& bindings = *pipeline_->bindings;
    set_ = allocator_.allocate(pipeline_->layout.setLayout);
    bufferInfos_.clear();
    imageInfos_.clear();
    writes_.clear();
    // Reserved up front: the writes point into these vectors.
    bufferInfos_.reserve(bindings.size());
    imageInfos_.reserve(bindings.size());
    for (const rhi::ShaderBinding& b : bindings) {
        // The validation layer has checked that every binding holds what the pipeline reads.
        const Bound* bound = &bound_[b.binding];
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.dstSet = set_;
        write.dstBinding = b.binding;
        write.descriptorCount = 1;
        write.descriptorType = descriptorType(b.kind);
        if (b.kind == rhi::BindingKind::UniformBuffer || b.kind == rhi::BindingKind::StorageBuffer) {
            bufferInfos_.push_back({bound->buffer, bound->storageOffset, bound->size});
            write.pBufferInfo = &bufferInfos_.back();
        } else {
            imageInfos_.push_back({bound->sampler, bound->view, bound->layout});
            write.pImageInfo = &imageInfos_.back();
        }
        writes_.push_back(write);
    }
    vkUpdateDescriptorSets(allocator_.device(), std::uint32_t(writes_.size()), writes_.data(), 0, nullptr);
}

} // namespace penumbra::vulkan
