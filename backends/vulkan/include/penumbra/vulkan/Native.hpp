#pragma once

// The Vulkan handles behind RHI objects, for code that drives Vulkan directly on the same objects
// (the RHI-versus-raw-Vulkan benchmark). Each function throws rhi::Error when the object was not
// created by a Vulkan device. The handles stay owned by the RHI objects: do not destroy them.
//
// State the RHI relies on: every texture rests in NativeTexture::restingLayout between command
// buffers (shader-read if sampled, else its attachment layout); passes and copies start and end
// there. Viewports are set with negative height (row 0 = top, front faces counter-clockwise).

#include "penumbra/rhi/Device.hpp"

#include <cstdint>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

// The Vulkan handles behind a device: instance, physical device, device, queue.
struct NativeDevice {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE; // the RHI submits here too; submit from one thread at a time
    std::uint32_t queueFamilyIndex = 0;
};

// The Vulkan handles behind a pipeline.
struct NativePipeline {
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    // The per-draw set, the last: uniform blocks are UNIFORM_BUFFER_DYNAMIC, textures COMBINED_IMAGE_SAMPLER, at their
    // GLSL binding numbers. Set 0 unless the pipeline lists binding set layouts, whose sets come first, in order.
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkRenderPass renderPass = VK_NULL_HANDLE; // the compatible render pass it was created with
};

// The Vulkan handles behind a framebuffer.
struct NativeFramebuffer {
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    // Clears colour and depth, like beginPass with a default PassDesc; ends in the resting layouts.
    VkRenderPass renderPass = VK_NULL_HANDLE;
};

// The Vulkan handles behind a texture.
struct NativeTexture {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE; // the sampled view: all layers, depth aspect only
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkImageLayout restingLayout = VK_IMAGE_LAYOUT_UNDEFINED;
};

// The native handles of a Vulkan device, for calls the RHI does not offer (tests, interop).
NativeDevice native(const rhi::Device& device);
// The VkBuffer behind an RHI buffer of a Vulkan device.
VkBuffer native(const rhi::Buffer& buffer);
// The Vulkan handles behind an RHI pipeline of a Vulkan device.
NativePipeline native(const rhi::Pipeline& pipeline);
// The Vulkan handles behind an RHI compute pipeline of a Vulkan device (no render pass; set 0 holds storage buffers as
// STORAGE_BUFFER descriptors).
NativePipeline native(const rhi::ComputePipeline& pipeline);
// The Vulkan handles behind an RHI framebuffer of a Vulkan device.
NativeFramebuffer native(const rhi::Framebuffer& framebuffer);
// The Vulkan handles behind an RHI texture of a Vulkan device.
NativeTexture native(const rhi::Texture& texture);
// The VkSampler behind an RHI sampler of a Vulkan device.
VkSampler native(const rhi::Sampler& sampler);
// The command buffer a list is recording into (valid until its next submit).
VkCommandBuffer native(const rhi::CommandList& commands);

// How a command list has bound descriptors since it was created, both bind points together: for tests that show
// which path a binding takes.
struct DescriptorCounts {
    std::uint64_t bindCalls = 0; // vkCmdBindDescriptorSets
    std::uint64_t bindingSetBinds = 0; // of those, the calls that bound a binding set's own descriptor set
    std::uint64_t setsWritten = 0; // descriptor sets written while recording: per draw, or for a set bound in parts
};
DescriptorCounts descriptorCounts(const rhi::CommandList& commands);

} // namespace penumbra::vulkan
