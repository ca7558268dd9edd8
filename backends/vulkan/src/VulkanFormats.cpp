#include "VulkanFormats.hpp"

#include "penumbra/rhi/Error.hpp"

namespace penumbra::vulkan {

VkFormat toVkFormat(rhi::Format format)
{
    switch (format) {
    case rhi::Format::RGBA8:
        return VK_FORMAT_R8G8B8A8_UNORM;
    case rhi::Format::RGBA16F:
        return VK_FORMAT_R16G16B16A16_SFLOAT;
    case rhi::Format::RGBA32F:
        return VK_FORMAT_R32G32B32A32_SFLOAT;
    case rhi::Format::D16:
        return VK_FORMAT_D16_UNORM;
    case rhi::Format::D24S8:
        return VK_FORMAT_D24_UNORM_S8_UINT;
    case rhi::Format::D32F:
        return VK_FORMAT_D32_SFLOAT;
    case rhi::Format::RGBA8_SRGB:
        return VK_FORMAT_R8G8B8A8_SRGB;
    case rhi::Format::R8:
        return VK_FORMAT_R8_UNORM;
    case rhi::Format::RG8:
        return VK_FORMAT_R8G8_UNORM;
    case rhi::Format::R16F:
        return VK_FORMAT_R16_SFLOAT;
    case rhi::Format::RG16F:
        return VK_FORMAT_R16G16_SFLOAT;
    case rhi::Format::R32F:
        return VK_FORMAT_R32_SFLOAT;
    }
    throw rhi::Error("Vulkan: unknown texture format");
}

VkImageAspectFlags fullAspect(rhi::Format format)
{
    if (format == rhi::Format::D24S8)
        return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
    return dataAspect(format);
}

VkImageAspectFlags dataAspect(rhi::Format format)
{
    return rhi::isDepthFormat(format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

VkFormat toVkFormat(rhi::VertexFormat format)
{
    switch (format) {
    case rhi::VertexFormat::Float:
        return VK_FORMAT_R32_SFLOAT;
    case rhi::VertexFormat::Float2:
        return VK_FORMAT_R32G32_SFLOAT;
    case rhi::VertexFormat::Float3:
        return VK_FORMAT_R32G32B32_SFLOAT;
    case rhi::VertexFormat::Float4:
        return VK_FORMAT_R32G32B32A32_SFLOAT;
    case rhi::VertexFormat::UByte4Norm:
        return VK_FORMAT_R8G8B8A8_UNORM;
    }
    throw rhi::Error("Vulkan: unknown vertex format");
}

VkPrimitiveTopology toVkTopology(rhi::PrimitiveTopology topology)
{
    switch (topology) {
    case rhi::PrimitiveTopology::TriangleList:
        return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    case rhi::PrimitiveTopology::TriangleStrip:
        return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
    case rhi::PrimitiveTopology::LineList:
        return VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
    case rhi::PrimitiveTopology::PointList:
        return VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    }
    throw rhi::Error("Vulkan: unknown primitive topology");
}

VkCullModeFlags toVkCullMode(rhi::CullMode cull)
{
    switch (cull) {
    case rhi::CullMode::None:
        return VK_CULL_MODE_NONE;
    case rhi::CullMode::Back:
        return VK_CULL_MODE_BACK_BIT;
    case rhi::CullMode::Front:
        return VK_CULL_MODE_FRONT_BIT;
    }
    throw rhi::Error("Vulkan: unknown cull mode");
}

VkCompareOp toVkCompareOp(rhi::CompareOp op)
{
    switch (op) {
    case rhi::CompareOp::Never:
        return VK_COMPARE_OP_NEVER;
    case rhi::CompareOp::Less:
        return VK_COMPARE_OP_LESS;
    case rhi::CompareOp::LessOrEqual:
        return VK_COMPARE_OP_LESS_OR_EQUAL;
    case rhi::CompareOp::Equal:
        return VK_COMPARE_OP_EQUAL;
    case rhi::CompareOp::Greater:
        return VK_COMPARE_OP_GREATER;
    case rhi::CompareOp::GreaterOrEqual:
        return VK_COMPARE_OP_GREATER_OR_EQUAL;
    case rhi::CompareOp::NotEqual:
        return VK_COMPARE_OP_NOT_EQUAL;
    case rhi::CompareOp::Always:
        return VK_COMPARE_OP_ALWAYS;
    }
    throw rhi::Error("Vulkan: unknown compare op");
}

VkBlendFactor toVkBlendFactor(rhi::BlendFactor factor)
{
    switch (factor) {
    case rhi::BlendFactor::Zero:
        return VK_BLEND_FACTOR_ZERO;
    case rhi::BlendFactor::One:
        return VK_BLEND_FACTOR_ONE;
    case rhi::BlendFactor::SrcColor:
        return VK_BLEND_FACTOR_SRC_COLOR;
    case rhi::BlendFactor::OneMinusSrcColor:
        return VK_BLEND_FACTOR_ONE_MINUS_SRC_COLOR;
    case rhi::BlendFactor::SrcAlpha:
        return VK_BLEND_FACTOR_SRC_ALPHA;
    case rhi::BlendFactor::OneMinusSrcAlpha:
        return VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    case rhi::BlendFactor::DstColor:
        return VK_BLEND_FACTOR_DST_COLOR;
    case rhi::BlendFactor::OneMinusDstColor:
        return VK_BLEND_FACTOR_ONE_MINUS_DST_COLOR;
    case rhi::BlendFactor::DstAlpha:
        return VK_BLEND_FACTOR_DST_ALPHA;
    case rhi::BlendFactor::OneMinusDstAlpha:
        return VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA;
    }
    throw rhi::Error("Vulkan: unknown blend factor");
}

VkBlendOp toVkBlendOp(rhi::BlendOp op)
{
    switch (op) {
    case rhi::BlendOp::Add:
        return VK_BLEND_OP_ADD;
    case rhi::BlendOp::Subtract:
        return VK_BLEND_OP_SUBTRACT;
    case rhi::BlendOp::ReverseSubtract:
        return VK_BLEND_OP_REVERSE_SUBTRACT;
    case rhi::BlendOp::Min:
        return VK_BLEND_OP_MIN;
    case rhi::BlendOp::Max:
        return VK_BLEND_OP_MAX;
    }
    throw rhi::Error("Vulkan: unknown blend op");
}

VkColorComponentFlags toVkColorMask(rhi::ColorMask mask)
{
    // rhi::ColorMask's bits are R=1, G=2, B=4, A=8, the same as VkColorComponentFlagBits.
    return static_cast<VkColorComponentFlags>(mask);
}

VkFilter toVkFilter(rhi::Filter filter) { return filter == rhi::Filter::Linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST; }

// MipFilter::None is the nearest mode with the LOD range rhi::samplerLodRange gives it.
VkSamplerMipmapMode toVkMipmapMode(rhi::MipFilter filter)
{
    return filter == rhi::MipFilter::Linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
}

VkSamplerAddressMode toVkAddressMode(rhi::AddressMode mode)
{
    switch (mode) {
    case rhi::AddressMode::ClampToEdge:
        return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case rhi::AddressMode::Repeat:
        return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case rhi::AddressMode::MirroredRepeat:
        return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    }
    throw rhi::Error("Vulkan: unknown address mode");
}

VkIndexType toVkIndexType(rhi::IndexType type)
{
    return type == rhi::IndexType::UInt16 ? VK_INDEX_TYPE_UINT16 : VK_INDEX_TYPE_UINT32;
}

VkPipelineStageFlags toVkStages(rhi::Stage stages)
{
    VkPipelineStageFlags flags = 0;
    const auto add = [&](rhi::Stage stage, VkPipelineStageFlags vk) {
        if (rhi::hasFlag(stages, stage))
            flags |= vk;
    };
    add(rhi::Stage::DrawIndirect, VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT);
    add(rhi::Stage::VertexInput, VK_PIPELINE_STAGE_VERTEX_INPUT_BIT);
    add(rhi::Stage::VertexShader, VK_PIPELINE_STAGE_VERTEX_SHADER_BIT);
    add(rhi::Stage::FragmentShader, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
    add(rhi::Stage::Attachments, VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                     VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT |
                                     VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT);
    add(rhi::Stage::ComputeShader, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
    add(rhi::Stage::Copy, VK_PIPELINE_STAGE_TRANSFER_BIT);
    add(rhi::Stage::Host, VK_PIPELINE_STAGE_HOST_BIT);
    return flags;
}

VkAccessFlags toVkAccess(rhi::Access access)
{
    VkAccessFlags flags = 0;
    const auto add = [&](rhi::Access a, VkAccessFlags vk) {
        if (rhi::hasFlag(access, a))
            flags |= vk;
    };
    add(rhi::Access::IndirectRead, VK_ACCESS_INDIRECT_COMMAND_READ_BIT);
    add(rhi::Access::VertexRead, VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT);
    add(rhi::Access::IndexRead, VK_ACCESS_INDEX_READ_BIT);
    add(rhi::Access::UniformRead, VK_ACCESS_UNIFORM_READ_BIT);
    add(rhi::Access::SampledRead | rhi::Access::StorageBufferRead | rhi::Access::StorageImageRead,
        VK_ACCESS_SHADER_READ_BIT);
    add(rhi::Access::StorageBufferWrite | rhi::Access::StorageImageWrite, VK_ACCESS_SHADER_WRITE_BIT);
    add(rhi::Access::AttachmentRead, VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
    add(rhi::Access::AttachmentWrite,
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    add(rhi::Access::CopyRead, VK_ACCESS_TRANSFER_READ_BIT);
    add(rhi::Access::CopyWrite, VK_ACCESS_TRANSFER_WRITE_BIT);
    add(rhi::Access::HostRead, VK_ACCESS_HOST_READ_BIT);
    return flags;
}

} // namespace penumbra::vulkan
