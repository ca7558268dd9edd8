#include "penumbra/vulkan/Native.hpp"

#include "VulkanCheck.hpp"
#include "VulkanCommandList.hpp"
#include "VulkanDevice.hpp"
#include "VulkanPipeline.hpp"
#include "VulkanRenderPass.hpp"
#include "VulkanResources.hpp"

namespace penumbra::vulkan {

NativeDevice native(const rhi::Device& device)
{
    const Context& c = vulkanObject<const VulkanDevice>(device, "native: the device").context();
    return {c.instance.handle(), c.physicalDevice, c.device, c.queue, c.queueFamily};
}

VkBuffer native(const rhi::Buffer& buffer)
{
    return vulkanObject<const VulkanBuffer>(buffer, "native: the buffer").handle();
}

NativePipeline native(const rhi::Pipeline& pipeline)
{
    const auto& vk = vulkanObject<const VulkanPipeline>(pipeline, "native: the pipeline");
    return {vk.handle(), vk.descriptors().layout, vk.descriptors().drawLayout, vk.renderPass()};
}

NativePipeline native(const rhi::ComputePipeline& pipeline)
{
    const auto& vk = vulkanObject<const VulkanComputePipeline>(pipeline, "native: the compute pipeline");
    return {vk.handle(), vk.descriptors().layout, vk.descriptors().drawLayout, VK_NULL_HANDLE};
}

NativeFramebuffer native(const rhi::Framebuffer& framebuffer)
{
    const auto& vk = vulkanObject<const VulkanFramebuffer>(framebuffer, "native: the framebuffer");
    return {vk.handle(), vk.renderPass(false, false)};
}

NativeTexture native(const rhi::Texture& texture)
{
    const auto& vk = vulkanObject<const VulkanTexture>(texture, "native: the texture");
    return {vk.image(), vk.sampledView(), vk.format(), vk.restingLayout()};
}

VkSampler native(const rhi::Sampler& sampler)
{
    return vulkanObject<const VulkanSampler>(sampler, "native: the sampler").handle();
}

VkCommandBuffer native(const rhi::CommandList& commands)
{
    return vulkanObject<const VulkanCommandList>(commands, "native: the command list").commandBuffer();
}

DescriptorCounts descriptorCounts(const rhi::CommandList& commands)
{
    return vulkanObject<const VulkanCommandList>(commands, "descriptorCounts: the command list").descriptorCounts();
}

} // namespace penumbra::vulkan
