#pragma once

#include "penumbra/rhi/Device.hpp"

#include <array>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

inline constexpr std::array allFormats{rhi::Format::RGBA8, rhi::Format::RGBA16F, rhi::Format::RGBA32F,
                                       rhi::Format::D16,   rhi::Format::D24S8,   rhi::Format::D32F};

VkFormat toVkFormat(rhi::Format format);
// Every aspect of the format (depth and stencil for D24S8): what barriers and attachments use.
VkImageAspectFlags fullAspect(rhi::Format format);
// The aspect that is sampled and copied: depth only for D24S8.
VkImageAspectFlags dataAspect(rhi::Format format);

VkFormat toVkFormat(rhi::VertexFormat format);
VkPrimitiveTopology toVkTopology(rhi::PrimitiveTopology topology);
VkCullModeFlags toVkCullMode(rhi::CullMode cull);
VkCompareOp toVkCompareOp(rhi::CompareOp op);
VkBlendFactor toVkBlendFactor(rhi::BlendFactor factor);
VkBlendOp toVkBlendOp(rhi::BlendOp op);
VkColorComponentFlags toVkColorMask(rhi::ColorMask mask);
VkFilter toVkFilter(rhi::Filter filter);
VkSamplerAddressMode toVkAddressMode(rhi::AddressMode mode);
VkIndexType toVkIndexType(rhi::IndexType type);

} // namespace penumbra::vulkan
