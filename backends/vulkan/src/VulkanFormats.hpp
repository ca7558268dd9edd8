#pragma once

#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/Hazards.hpp"

#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

VkFormat toVkFormat(rhi::Format format);
// Every aspect of the format (depth and stencil for D24S8): what barriers and attachments use.
VkImageAspectFlags fullAspect(rhi::Format format);
// The aspect that is sampled and copied: depth only for D24S8.
VkImageAspectFlags dataAspect(rhi::Format format);

VkFormat toVkFormat(rhi::VertexFormat format);
VkPrimitiveTopology toVkTopology(rhi::PrimitiveTopology topology);
VkCullModeFlags toVkCullMode(rhi::CullMode cull);
// The RHI's barrier stages and accesses (rhi/Hazards.hpp) in Vulkan 1.0 terms.
VkPipelineStageFlags toVkStages(rhi::Stage stages);
VkAccessFlags toVkAccess(rhi::Access access);
VkCompareOp toVkCompareOp(rhi::CompareOp op);
VkBlendFactor toVkBlendFactor(rhi::BlendFactor factor);
VkBlendOp toVkBlendOp(rhi::BlendOp op);
VkColorComponentFlags toVkColorMask(rhi::ColorMask mask);
VkFilter toVkFilter(rhi::Filter filter);
VkSamplerMipmapMode toVkMipmapMode(rhi::MipFilter filter);
VkSamplerAddressMode toVkAddressMode(rhi::AddressMode mode);
VkIndexType toVkIndexType(rhi::IndexType type);

} // namespace penumbra::vulkan
