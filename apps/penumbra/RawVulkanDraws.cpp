#include "RawDraws.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/vulkan/Native.hpp"

#include <array>
#include <fmt/format.h>

namespace penumbra::apps {
namespace {

void check(VkResult result, const char* call)
{
    if (result != VK_SUCCESS)
        throw rhi::Error(fmt::format("raw Vulkan benchmark: {} failed ({})", call, int(result)));
}

// What an experienced Vulkan programmer writes for this frame: one command buffer, one
// descriptor set with a dynamic uniform buffer, one vkCmdBindDescriptorSets + vkCmdDrawIndexed per mesh.
class RawVulkanDraws final : public RawDraws {
public:
    RawVulkanDraws(rhi::Device& device, const DrawScene& scene)
        : scene_(scene), device_(vulkan::native(device)), pipeline_(vulkan::native(scene.pipeline())),
          framebuffer_(vulkan::native(scene.framebuffer())), vertices_(vulkan::native(scene.vertices())),
          indices_(vulkan::native(scene.indices())), clearDepth_(device.conventions().clearDepth())
    {
        const VkDevice d = device_.device;
        const VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO, nullptr,
                                               VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                               device_.queueFamilyIndex};
        check(vkCreateCommandPool(d, &poolInfo, nullptr, &commandPool_), "vkCreateCommandPool");
        const VkCommandBufferAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, nullptr,
                                                       commandPool_, VK_COMMAND_BUFFER_LEVEL_PRIMARY, 1};
        check(vkAllocateCommandBuffers(d, &allocateInfo, &commandBuffer_), "vkAllocateCommandBuffers");
        const VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO, nullptr, 0};
        check(vkCreateFence(d, &fenceInfo, nullptr, &fence_), "vkCreateFence");

        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1};
        const VkDescriptorPoolCreateInfo descriptorPoolInfo{
            VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO, nullptr, 0, 1, 1, &size};
        check(vkCreateDescriptorPool(d, &descriptorPoolInfo, nullptr, &descriptorPool_), "vkCreateDescriptorPool");
        const VkDescriptorSetAllocateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO, nullptr,
                                                  descriptorPool_, 1, &pipeline_.setLayout};
        check(vkAllocateDescriptorSets(d, &setInfo, &set_), "vkAllocateDescriptorSets");
        const VkDescriptorBufferInfo bufferInfo{vulkan::native(scene.objects()), 0, DrawScene::objectSize};
        const VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,    nullptr, set_,        0,      0, 1,
                                         VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, nullptr, &bufferInfo, nullptr};
        vkUpdateDescriptorSets(d, 1, &write, 0, nullptr);
    }

    ~RawVulkanDraws() override
    {
        vkDestroyDescriptorPool(device_.device, descriptorPool_, nullptr);
        vkDestroyFence(device_.device, fence_, nullptr);
        vkDestroyCommandPool(device_.device, commandPool_, nullptr);
    }

    void frame() override
    {
        const VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO, nullptr,
                                             VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT, nullptr};
        check(vkBeginCommandBuffer(commandBuffer_, &begin), "vkBeginCommandBuffer");
        std::array<VkClearValue, 2> clears{};
        clears[1].depthStencil = {clearDepth_, 0};
        const VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO,
                                         nullptr,
                                         framebuffer_.renderPass,
                                         framebuffer_.framebuffer,
                                         {{0, 0}, {DrawScene::size, DrawScene::size}},
                                         std::uint32_t(clears.size()),
                                         clears.data()};
        vkCmdBeginRenderPass(commandBuffer_, &pass, VK_SUBPASS_CONTENTS_INLINE);
        // Negative height: the same row-0-at-top convention the RHI uses.
        const VkViewport viewport{0, float(DrawScene::size), float(DrawScene::size), -float(DrawScene::size), 0, 1};
        vkCmdSetViewport(commandBuffer_, 0, 1, &viewport);
        const VkRect2D scissor{{0, 0}, {DrawScene::size, DrawScene::size}};
        vkCmdSetScissor(commandBuffer_, 0, 1, &scissor);
        vkCmdSetDepthBias(commandBuffer_, 0.0f, 0.0f, 0.0f);
        vkCmdBindPipeline(commandBuffer_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.pipeline);
        const VkDeviceSize zero = 0;
        vkCmdBindVertexBuffers(commandBuffer_, 0, 1, &vertices_, &zero);
        vkCmdBindIndexBuffer(commandBuffer_, indices_, 0, VK_INDEX_TYPE_UINT16);
        for (std::uint32_t i = 0; i < scene_.count(); ++i) {
            const std::uint32_t offset = std::uint32_t(scene_.objectStride() * i);
            vkCmdBindDescriptorSets(commandBuffer_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.layout, 0, 1, &set_, 1,
                                    &offset);
            vkCmdDrawIndexed(commandBuffer_, scene_.indexCount(), 1, 0, 0, 0);
        }
        vkCmdEndRenderPass(commandBuffer_);
        check(vkEndCommandBuffer(commandBuffer_), "vkEndCommandBuffer");

        const VkSubmitInfo submit{
            VK_STRUCTURE_TYPE_SUBMIT_INFO, nullptr, 0, nullptr, nullptr, 1, &commandBuffer_, 0, nullptr};
        check(vkQueueSubmit(device_.queue, 1, &submit, fence_), "vkQueueSubmit");
        check(vkWaitForFences(device_.device, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
        check(vkResetFences(device_.device, 1, &fence_), "vkResetFences");
        check(vkResetCommandBuffer(commandBuffer_, 0), "vkResetCommandBuffer");
    }

private:
    const DrawScene& scene_;
    vulkan::NativeDevice device_;
    vulkan::NativePipeline pipeline_;
    vulkan::NativeFramebuffer framebuffer_;
    VkBuffer vertices_, indices_;
    float clearDepth_;
    VkCommandPool commandPool_ = VK_NULL_HANDLE;
    VkCommandBuffer commandBuffer_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

} // namespace

std::unique_ptr<RawDraws> createRawVulkanDraws(rhi::Device& device, const DrawScene& scene)
{
    return std::make_unique<RawVulkanDraws>(device, scene);
}

} // namespace penumbra::apps
