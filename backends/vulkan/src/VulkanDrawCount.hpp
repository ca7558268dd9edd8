#pragma once

#include "VulkanContext.hpp"
#include "VulkanDescriptors.hpp"

#include <memory>
#include <vector>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

class VulkanBuffer;
class VulkanComputePipeline;
class VulkanShader;

// Draw counts where the device reads none (Capabilities::drawIndirectCount false). A command list suspends its pass,
// calls patch(), and resumes the pass with its attachments loaded to draw all maxDrawCount commands of the buffer
// patch() returns: a compute dispatch has copied them there, with instanceCount 0 in every command past the count,
// and a command of no instances draws nothing (Vulkan 1.3 section 21.3). Transfers and dispatches are not allowed
// inside a render pass instance, hence the suspension.
class DrawCountEmulation {
public:
    explicit DrawCountEmulation(std::shared_ptr<Context> context);
    ~DrawCountEmulation();

    // Byte offset of the first patched command in patch()'s buffer.
    static constexpr VkDeviceSize commandsOffset = 16;

    // Records, outside any pass, the copy of maxDrawCount commands of `commandWords` uint32 from `offset` of
    // `arguments`, counted by the uint32 at countOffset of `count`; returns the buffer the draw then reads.
    VkBuffer patch(VkCommandBuffer commands, const VulkanBuffer& arguments, VkDeviceSize offset,
                   const VulkanBuffer& count, VkDeviceSize countOffset, std::uint32_t maxDrawCount,
                   std::uint32_t commandWords);
    // After submit: the patched buffers and descriptor sets are no longer read.
    void reset();

private:
    std::shared_ptr<Context> context_;
    std::unique_ptr<VulkanShader> shader_; // made on the first patch
    std::unique_ptr<VulkanComputePipeline> pipeline_;
    DescriptorBinder descriptors_;
    std::vector<std::unique_ptr<VulkanBuffer>> patched_;
};

} // namespace penumbra::vulkan
