// The copy commands of VulkanCommandList.

#include "VulkanCheck.hpp"
#include "VulkanCommandList.hpp"
#include "VulkanFormats.hpp"
#include "VulkanResources.hpp"

#include "penumbra/rhi/BackendSupport.hpp"
#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::vulkan {
namespace {

void checkLayer(std::string_view what, const rhi::TextureDesc& desc, std::uint32_t layer)
{
    if (layer >= desc.layers)
        throw rhi::Error(fmt::format("{}: layer {} of texture '{}' is out of range [0, {}]", what, layer,
                                     desc.debugName, desc.layers - 1));
}

void checkBufferRange(std::string_view what, const rhi::BufferDesc& desc, std::uint64_t offset, std::uint64_t size)
{
    if (offset > desc.size || size > desc.size - offset)
        throw rhi::Error(fmt::format("{}: {} bytes at offset {} exceed buffer '{}' ({} bytes)", what, size, offset,
                                     desc.debugName, desc.size));
}

} // namespace

void VulkanCommandList::copyBuffer(const rhi::Buffer& src, std::uint64_t srcOffset, rhi::Buffer& dst,
                                   std::uint64_t dstOffset, std::uint64_t size)
{
    requireOutsidePass("copyBuffer");
    const auto& from = vulkanObject<const VulkanBuffer>(src, "copyBuffer: the source");
    const auto& to = vulkanObject<const VulkanBuffer>(dst, "copyBuffer: the destination");
    checkBufferRange("copyBuffer source", from.desc(), srcOffset, size);
    checkBufferRange("copyBuffer destination", to.desc(), dstOffset, size);
    if (size == 0)
        return;
    fullBarrier(commands_);
    const VkBufferCopy region{srcOffset, dstOffset, size};
    vkCmdCopyBuffer(commands_, from.handle(), to.handle(), 1, &region);
    fullBarrier(commands_);
}

void VulkanCommandList::copyTexture(const rhi::Texture& src, std::uint32_t srcLayer, rhi::Texture& dst,
                                    std::uint32_t dstLayer)
{
    requireOutsidePass("copyTexture");
    const auto& from = vulkanObject<const VulkanTexture>(src, "copyTexture: the source");
    const auto& to = vulkanObject<const VulkanTexture>(dst, "copyTexture: the destination");
    const rhi::TextureDesc& a = from.desc();
    const rhi::TextureDesc& b = to.desc();
    checkLayer("copyTexture source", a, srcLayer);
    checkLayer("copyTexture destination", b, dstLayer);
    if (a.width != b.width || a.height != b.height || a.format != b.format)
        throw rhi::Error(fmt::format("copyTexture: '{}' is {}x{} {} but '{}' is {}x{} {}", a.debugName, a.width,
                                     a.height, rhi::formatName(a.format), b.debugName, b.width, b.height,
                                     rhi::formatName(b.format)));
    if (&from == &to && srcLayer == dstLayer)
        throw rhi::Error(fmt::format("copyTexture: layer {} of '{}' onto itself", srcLayer, a.debugName));

    from.transition(commands_, srcLayer, from.restingLayout(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    to.transition(commands_, dstLayer, to.restingLayout(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    VkImageCopy region{};
    region.srcSubresource = {fullAspect(a.format), 0, srcLayer, 1};
    region.dstSubresource = {fullAspect(b.format), 0, dstLayer, 1};
    region.extent = {a.width, a.height, 1};
    vkCmdCopyImage(commands_, from.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.image(),
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    from.transition(commands_, srcLayer, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, from.restingLayout());
    to.transition(commands_, dstLayer, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, to.restingLayout());
}

void VulkanCommandList::copyTextureToBuffer(const rhi::Texture& src, std::uint32_t layer, rhi::Buffer& dst,
                                            std::uint64_t dstOffset)
{
    requireOutsidePass("copyTextureToBuffer");
    const auto& from = vulkanObject<const VulkanTexture>(src, "copyTextureToBuffer: the source");
    const auto& to = vulkanObject<const VulkanBuffer>(dst, "copyTextureToBuffer: the destination");
    const rhi::TextureDesc& desc = from.desc();
    checkLayer("copyTextureToBuffer", desc, layer);
    checkBufferRange("copyTextureToBuffer", to.desc(), dstOffset, rhi::layerSize(desc));
    // Vulkan's rule: texel-size aligned offsets, and multiples of 4 for depth.
    const std::uint32_t alignment = rhi::isDepthFormat(desc.format) ? 4 : rhi::texelSize(desc.format);
    if (dstOffset % alignment)
        throw rhi::Error(fmt::format("copyTextureToBuffer: offset {} is not a multiple of {} for {}", dstOffset,
                                     alignment, rhi::formatName(desc.format)));

    from.transition(commands_, layer, from.restingLayout(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    VkBufferImageCopy region{};
    region.bufferOffset = dstOffset;
    region.imageSubresource = {dataAspect(desc.format), 0, layer, 1};
    region.imageExtent = {desc.width, desc.height, 1};
    vkCmdCopyImageToBuffer(commands_, from.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.handle(), 1, &region);
    from.transition(commands_, layer, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, from.restingLayout());
    fullBarrier(commands_);
}

} // namespace penumbra::vulkan
