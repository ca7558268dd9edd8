// The copy and resolve commands of VulkanCommandList.

#include "VulkanCheck.hpp"
#include "VulkanCommandList.hpp"
#include "VulkanFormats.hpp"
#include "VulkanResources.hpp"

#include "penumbra/rhi/BackendSupport.hpp"
#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>
#include <vector>

namespace penumbra::vulkan {
void VulkanCommandList::apiCopyBuffer(const rhi::Buffer& src, std::uint64_t srcOffset, rhi::Buffer& dst,
                                      std::uint64_t dstOffset, std::uint64_t size)
{
    const auto& from = vulkanObject<const VulkanBuffer>(src, "copyBuffer: the source");
    const auto& to = vulkanObject<const VulkanBuffer>(dst, "copyBuffer: the destination");
    if (size == 0)
        return;
    // Earlier passes and copies are ordered before this one by their own dependencies, dispatches by the RHI's
    // hazard tracker; the full barrier after orders this copy before everything later.
    const VkBufferCopy region{srcOffset, dstOffset, size};
    vkCmdCopyBuffer(commands_, from.handle(), to.handle(), 1, &region);
    fullBarrier(commands_);
}

void VulkanCommandList::apiCopyTexture(const rhi::Texture& src, std::uint32_t srcLayer, rhi::Texture& dst,
                                       std::uint32_t dstLayer)
{
    const auto& from = vulkanObject<const VulkanTexture>(src, "copyTexture: the source");
    const auto& to = vulkanObject<const VulkanTexture>(dst, "copyTexture: the destination");
    const rhi::TextureDesc& desc = from.desc();

    from.transition(commands_, srcLayer, from.restingLayout(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    to.transition(commands_, dstLayer, to.restingLayout(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    std::vector<VkImageCopy> regions(desc.mipLevels);
    for (std::uint32_t level = 0; level < desc.mipLevels; ++level) {
        regions[level].srcSubresource = {fullAspect(desc.format), level, srcLayer, 1};
        regions[level].dstSubresource = {fullAspect(desc.format), level, dstLayer, 1};
        regions[level].extent = {rhi::mipExtent(desc.width, level), rhi::mipExtent(desc.height, level), 1};
    }
    vkCmdCopyImage(commands_, from.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.image(),
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, std::uint32_t(regions.size()), regions.data());
    from.transition(commands_, srcLayer, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, from.restingLayout());
    to.transition(commands_, dstLayer, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, to.restingLayout());
}

void VulkanCommandList::apiCopyTextureToBuffer(const rhi::Texture& src, std::uint32_t layer, std::uint32_t level,
                                               rhi::Buffer& dst, std::uint64_t dstOffset)
{
    const auto& from = vulkanObject<const VulkanTexture>(src, "copyTextureToBuffer: the source");
    const auto& to = vulkanObject<const VulkanBuffer>(dst, "copyTextureToBuffer: the destination");
    const rhi::TextureDesc& desc = from.desc();

    from.transition(commands_, layer, from.restingLayout(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    VkBufferImageCopy region{};
    region.bufferOffset = dstOffset;
    region.imageSubresource = {dataAspect(desc.format), level, layer, 1};
    region.imageExtent = {rhi::mipExtent(desc.width, level), rhi::mipExtent(desc.height, level), 1};
    vkCmdCopyImageToBuffer(commands_, from.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.handle(), 1, &region);
    from.transition(commands_, layer, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, from.restingLayout());
    fullBarrier(commands_);
}

void VulkanCommandList::apiResolveTexture(const rhi::Texture& src, rhi::Texture& dst)
{
    const auto& from = vulkanObject<const VulkanTexture>(src, "resolveTexture: the source");
    const auto& to = vulkanObject<const VulkanTexture>(dst, "resolveTexture: the destination");
    const rhi::TextureDesc& desc = from.desc();

    from.transition(commands_, 0, from.restingLayout(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    to.transition(commands_, 0, to.restingLayout(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    VkImageResolve region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.extent = {desc.width, desc.height, 1};
    vkCmdResolveImage(commands_, from.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.image(),
                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    from.transition(commands_, 0, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, from.restingLayout());
    to.transition(commands_, 0, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, to.restingLayout());
}

} // namespace penumbra::vulkan
