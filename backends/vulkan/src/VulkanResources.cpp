#include "VulkanResources.hpp"

#include "VulkanCheck.hpp"
#include "VulkanFormats.hpp"

#include "penumbra/rhi/BackendSupport.hpp"
#include "penumbra/rhi/ValidationRules.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/HugePages.hpp"
#include "penumbra/rhi/MemorySize.hpp"

#include <algorithm>
#include <cstring>
#include <fmt/format.h>

namespace penumbra::vulkan {
namespace {

VkBufferUsageFlags bufferUsage(rhi::BufferUsage usage)
{
    VkBufferUsageFlags flags = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    if (rhi::hasFlag(usage, rhi::BufferUsage::Vertex))
        flags |= VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
    if (rhi::hasFlag(usage, rhi::BufferUsage::Index))
        flags |= VK_BUFFER_USAGE_INDEX_BUFFER_BIT;
    if (rhi::hasFlag(usage, rhi::BufferUsage::Uniform))
        flags |= VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
    if (rhi::hasFlag(usage, rhi::BufferUsage::Storage))
        flags |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    // Indirect arguments and counts are also read as storage buffers by the draw-count emulation
    // (VulkanDrawCount.cpp).
    if (rhi::hasFlag(usage, rhi::BufferUsage::Indirect))
        flags |= VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    return flags;
}

// An empty buffer (a scene with nothing to draw) is valid in the RHI; Vulkan needs at least a byte.
VkDeviceSize allocationSize(const rhi::BufferDesc& desc) { return std::max<VkDeviceSize>(desc.size, 1); }

VkImageLayout attachmentLayout(rhi::Format format)
{
    return rhi::isDepthFormat(format) ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL
                                      : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
}

VkImageLayout restingLayoutOf(const rhi::TextureDesc& desc)
{
    // A storage image must be GENERAL while shaders load and store it (Vulkan 1.3 section 14.1.1); resting there
    // spares a transition around every dispatch, and GENERAL serves sampling, copies and attachments too.
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::Storage))
        return VK_IMAGE_LAYOUT_GENERAL;
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::Sampled))
        return VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::RenderTarget))
        return attachmentLayout(desc.format);
    return VK_IMAGE_LAYOUT_GENERAL;
}

VkImageViewType sampledViewType(const rhi::TextureDesc& desc)
{
    if (desc.cube)
        return VK_IMAGE_VIEW_TYPE_CUBE_ARRAY;
    return desc.array || desc.layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
}

// The validation layer checks the format features each usage needs against Capabilities::formats.
VkImageUsageFlags imageUsage(const rhi::TextureDesc& desc)
{
    VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::Sampled))
        usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::Storage))
        usage |= VK_IMAGE_USAGE_STORAGE_BIT;
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::RenderTarget))
        usage |= rhi::isDepthFormat(desc.format) ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT
                                                 : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    return usage;
}

// A CPU device's (lavapipe's) device memory is process memory that vkMapMemory returns as it is: the hint reaches the
// pages its copies into the image first touch. A large texture only; other devices' memory is not process memory.
void adviseHugePagesOf(const Context& context, VkDeviceMemory memory, const VkMemoryAllocateInfo& alloc)
{
    constexpr VkDeviceSize kLargeTexture = VkDeviceSize(4) << 20;
    VkPhysicalDeviceMemoryProperties properties;
    vkGetPhysicalDeviceMemoryProperties(context.physicalDevice, &properties);
    if (alloc.allocationSize < kLargeTexture ||
        !(properties.memoryTypes[alloc.memoryTypeIndex].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT))
        return;
    void* mapped = nullptr;
    check(vkMapMemory(context.device, memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
    rhi::adviseHugePages(mapped, alloc.allocationSize);
    vkUnmapMemory(context.device, memory);
}

} // namespace

MappedBuffer::MappedBuffer(std::shared_ptr<Context> context, VkDeviceSize size, VkBufferUsageFlags usage)
    : context_(std::move(context))
{
    const VkDevice device = context_->device;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    buffer_ = createOwned<UniqueBuffer>(device, vkCreateBuffer, info, "vkCreateBuffer");
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device, buffer_.get(), &requirements);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = requirements.size;
    const VkMemoryPropertyFlags hostVisible =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    alloc.memoryTypeIndex = context_->memoryType(requirements.memoryTypeBits, hostVisible, hostVisible);
    memory_ = createOwned<UniqueMemory>(device, vkAllocateMemory, alloc, "vkAllocateMemory");
    check(vkBindBufferMemory(device, buffer_.get(), memory_.get(), 0), "vkBindBufferMemory");
    void* mapped = nullptr;
    check(vkMapMemory(device, memory_.get(), 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
    mapped_ = static_cast<std::byte*>(mapped);
}

VulkanBuffer::VulkanBuffer(std::shared_ptr<Context> context, const rhi::BufferDesc& desc)
    : desc_(desc), buffer_(context, allocationSize(desc), bufferUsage(desc.usage))
{
    context->setName(VK_OBJECT_TYPE_BUFFER, buffer_.handle(), desc.debugName);
}

void VulkanBuffer::write(std::uint64_t offset, std::span<const std::byte> data)
{
    rhi::writeMappedBuffer(desc_, buffer_.data(), offset, data);
}

void VulkanBuffer::read(std::uint64_t offset, std::span<std::byte> data) const
{
    rhi::readMappedBuffer(desc_, buffer_.data(), offset, data);
}

VulkanTexture::VulkanTexture(std::shared_ptr<Context> context, const rhi::TextureDesc& desc)
    : context_(std::move(context)), desc_(desc), format_(toVkFormat(desc.format)), restingLayout_(restingLayoutOf(desc))
{
    const VkDevice device = context_->device;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.flags = desc.cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format_;
    info.extent = {desc.width, desc.height, 1};
    info.mipLevels = desc.mipLevels;
    info.arrayLayers = desc.layers;
    info.samples = VkSampleCountFlagBits(desc.samples); // 1, 2, 4, 8: the RHI's counts are the flag bits
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = imageUsage(desc);
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    image_ = createOwned<UniqueImage>(device, vkCreateImage, info, "vkCreateImage");
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device, image_.get(), &requirements);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = requirements.size;
    alloc.memoryTypeIndex = context_->memoryType(requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0);
    memory_ = createOwned<UniqueMemory>(device, vkAllocateMemory, alloc,
                                        fmt::format("vkAllocateMemory of {} for {}", rhi::byteSize(requirements.size),
                                                    rhi::describeAllocation(desc)));
    check(vkBindImageMemory(device, image_.get(), memory_.get(), 0), "vkBindImageMemory");
    if (context_->properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU)
        adviseHugePagesOf(*context_, memory_.get(), alloc);

    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = image_.get();
    viewInfo.viewType = sampledViewType(desc);
    viewInfo.format = format_;
    viewInfo.subresourceRange = {dataAspect(desc.format), 0, desc.mipLevels, 0, desc.layers};
    view_ = createOwned<UniqueImageView>(device, vkCreateImageView, viewInfo, "vkCreateImageView");
    // A storage image view addresses one level (Vulkan 1.3, VUID-VkWriteDescriptorSet-descriptorType-00336 needs
    // levelCount 1 for a storage image), so there is one per level.
    if (rhi::hasFlag(desc.usage, rhi::TextureUsage::Storage))
        for (std::uint32_t level = 0; level < desc.mipLevels; ++level) {
            viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
            viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, 1, 0, 1};
            storageViews_.push_back(
                createOwned<UniqueImageView>(device, vkCreateImageView, viewInfo, "vkCreateImageView"));
        }
    context_->setName(VK_OBJECT_TYPE_IMAGE, image_.get(), desc.debugName);
    context_->setName(VK_OBJECT_TYPE_IMAGE_VIEW, view_.get(), desc.debugName);

    context_->runOnce([&](VkCommandBuffer commandBuffer) {
        transition(commandBuffer, ~0u, VK_IMAGE_LAYOUT_UNDEFINED, restingLayout_);
    });
}

UniqueImageView VulkanTexture::createAttachmentView(std::uint32_t layer) const
{
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image_.get();
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = format_;
    info.subresourceRange = {fullAspect(desc_.format), 0, 1, layer, 1};
    return createOwned<UniqueImageView>(context_->device, vkCreateImageView, info, "vkCreateImageView");
}

void transitionImage(VkCommandBuffer commandBuffer, VkImage image, const VkImageSubresourceRange& range,
                     VkImageLayout from, VkImageLayout to)
{
    VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = range;
    vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &barrier);
}

void VulkanTexture::transition(VkCommandBuffer commandBuffer, std::uint32_t layer, VkImageLayout from,
                               VkImageLayout to) const
{
    const VkImageAspectFlags aspect = fullAspect(desc_.format);
    transitionImage(commandBuffer, image_.get(),
                    layer == ~0u ? VkImageSubresourceRange{aspect, 0, desc_.mipLevels, 0, desc_.layers}
                                 : VkImageSubresourceRange{aspect, 0, desc_.mipLevels, layer, 1},
                    from, to);
}

void VulkanTexture::upload(std::uint32_t layer, std::uint32_t level, std::span<const std::byte> data,
                           MappedBuffer& staging)
{
    std::memcpy(staging.data(), data.data(), data.size());
    context_->runOnce([&](VkCommandBuffer commandBuffer) {
        transition(commandBuffer, layer, restingLayout_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        VkBufferImageCopy region{};
        region.imageSubresource = {dataAspect(desc_.format), level, layer, 1};
        region.imageExtent = {rhi::mipExtent(desc_.width, level), rhi::mipExtent(desc_.height, level), 1};
        vkCmdCopyBufferToImage(commandBuffer, staging.handle(), image_.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                               &region);
        transition(commandBuffer, layer, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, restingLayout_);
    });
}

VulkanSampler::VulkanSampler(std::shared_ptr<Context> context, const rhi::SamplerDesc& desc)
    : context_(std::move(context)), desc_(desc)
{
    const rhi::LodRange lod = rhi::samplerLodRange(desc);
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = toVkFilter(desc.magFilter);
    info.minFilter = toVkFilter(desc.minFilter);
    info.mipmapMode = toVkMipmapMode(desc.mipFilter);
    info.addressModeU = toVkAddressMode(desc.addressU);
    info.addressModeV = toVkAddressMode(desc.addressV);
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.anisotropyEnable = desc.maxAnisotropy > 1.0f;
    info.maxAnisotropy = desc.maxAnisotropy;
    info.compareEnable = desc.compare;
    info.compareOp = toVkCompareOp(context_->conventions.shadowCompareOp());
    info.minLod = lod.min;
    info.maxLod = lod.max;
    info.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    sampler_ = createOwned<UniqueSampler>(context_->device, vkCreateSampler, info, "vkCreateSampler");
    context_->setName(VK_OBJECT_TYPE_SAMPLER, sampler_.get(), desc.debugName);
}

VulkanTimestampQueries::VulkanTimestampQueries(std::shared_ptr<Context> context, std::uint32_t count)
    : context_(std::move(context)), count_(count)
{
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = count;
    pool_ = createOwned<UniqueQueryPool>(context_->device, vkCreateQueryPool, info, "vkCreateQueryPool");
    // Reset now so that reading a query that was never written reports it instead of being invalid.
    context_->runOnce(
        [&](VkCommandBuffer commandBuffer) { vkCmdResetQueryPool(commandBuffer, pool_.get(), 0, count); });
}

std::vector<double> VulkanTimestampQueries::readNanoseconds() const
{
    // Pairs of (value, availability); no WAIT flag, so a query never written cannot hang us.
    std::vector<std::uint64_t> results(std::size_t(count_) * 2);
    const VkResult result =
        vkGetQueryPoolResults(context_->device, pool_.get(), 0, count_, results.size() * sizeof(std::uint64_t),
                              results.data(), 2 * sizeof(std::uint64_t),
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
    if (result != VK_NOT_READY)
        check(result, "vkGetQueryPoolResults");
    const double period = context_->properties.limits.timestampPeriod;
    std::vector<double> nanoseconds(count_);
    for (std::uint32_t i = 0; i < count_; ++i) {
        if (results[2 * i + 1] == 0)
            throw rhi::Error(fmt::format("readTimestamps: query {} was not written by a submitted command list", i));
        nanoseconds[i] = double(results[2 * i]) * period;
    }
    return nanoseconds;
}

} // namespace penumbra::vulkan
