#include "RawFrames.hpp"
#include "RawVulkanCommands.hpp"

#include <array>

namespace penumbra::apps {
namespace {

// What an experienced Vulkan programmer writes for this frame: one command buffer, one descriptor set with a dynamic
// uniform buffer, one vkCmdBindDescriptorSets and one vkCmdDrawIndexed (or vkCmdDrawIndexedIndirect) per mesh.
class RawVulkanDraws final : public RawFrame {
public:
    RawVulkanDraws(rhi::Device& device, const DrawScene& scene, DrawCall call)
        : scene_(scene), call_(call), commands_(vulkan::native(device)), pipeline_(vulkan::native(scene.pipeline())),
          framebuffer_(vulkan::native(scene.framebuffer())), vertices_(vulkan::native(scene.vertices())),
          indices_(vulkan::native(scene.indices())), arguments_(vulkan::native(scene.indirectArguments())),
          set_(vulkan::native(device).device, pipeline_.setLayout, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC,
               vulkan::native(scene.objects()), DrawScene::objectSize),
          clearDepth_(device.conventions().clearDepth())
    {
    }

    void frame() override
    {
        const VkCommandBuffer commandBuffer = commands_.begin();
        std::array<VkClearValue, 2> clears{};
        clears[1].depthStencil = {clearDepth_, 0};
        const VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO,
                                         nullptr,
                                         framebuffer_.renderPass,
                                         framebuffer_.framebuffer,
                                         {{0, 0}, {DrawScene::size, DrawScene::size}},
                                         std::uint32_t(clears.size()),
                                         clears.data()};
        vkCmdBeginRenderPass(commandBuffer, &pass, VK_SUBPASS_CONTENTS_INLINE);
        // Negative height: the same row-0-at-top convention the RHI uses.
        const VkViewport viewport{0, float(DrawScene::size), float(DrawScene::size), -float(DrawScene::size), 0, 1};
        vkCmdSetViewport(commandBuffer, 0, 1, &viewport);
        const VkRect2D scissor{{0, 0}, {DrawScene::size, DrawScene::size}};
        vkCmdSetScissor(commandBuffer, 0, 1, &scissor);
        vkCmdSetDepthBias(commandBuffer, 0.0f, 0.0f, 0.0f);
        vkCmdBindPipeline(commandBuffer, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.pipeline);
        const VkDeviceSize zero = 0;
        vkCmdBindVertexBuffers(commandBuffer, 0, 1, &vertices_, &zero);
        vkCmdBindIndexBuffer(commandBuffer, indices_, 0, VK_INDEX_TYPE_UINT16);
        const VkDescriptorSet set = set_.set();
        for (std::uint32_t i = 0; i < scene_.count(); ++i) {
            const std::uint32_t offset = std::uint32_t(scene_.objectStride() * i);
            vkCmdBindDescriptorSets(commandBuffer, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.layout, 0, 1, &set, 1,
                                    &offset);
            if (call_ == DrawCall::Indirect)
                vkCmdDrawIndexedIndirect(commandBuffer, arguments_, VkDeviceSize(DrawScene::indirectStride) * i, 1,
                                         DrawScene::indirectStride);
            else
                vkCmdDrawIndexed(commandBuffer, scene_.indexCount(), 1, 0, 0, 0);
        }
        vkCmdEndRenderPass(commandBuffer);
        commands_.submitAndWait();
    }

private:
    const DrawScene& scene_;
    DrawCall call_;
    RawVulkanCommands commands_;
    vulkan::NativePipeline pipeline_;
    vulkan::NativeFramebuffer framebuffer_;
    VkBuffer vertices_, indices_, arguments_;
    RawVulkanDescriptorSet set_;
    float clearDepth_;
};

// What an experienced Vulkan programmer writes for this work: the pipeline and one descriptor set bound once, then
// each vkCmdDispatch after a compute-to-compute memory barrier for the one before it.
class RawVulkanDispatches final : public RawFrame {
public:
    RawVulkanDispatches(rhi::Device& device, const DispatchScene& scene)
        : scene_(scene), commands_(vulkan::native(device)), pipeline_(vulkan::native(scene.pipeline())),
          set_(vulkan::native(device).device, pipeline_.setLayout, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
               vulkan::native(scene.counters()), sizeof(DispatchScene::Counters))
    {
    }

    void frame() override
    {
        const VkCommandBuffer commandBuffer = commands_.begin();
        vkCmdBindPipeline(commandBuffer, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.pipeline);
        const VkDescriptorSet set = set_.set();
        vkCmdBindDescriptorSets(commandBuffer, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.layout, 0, 1, &set, 0,
                                nullptr);
        const VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr, VK_ACCESS_SHADER_WRITE_BIT,
                                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
        for (std::uint32_t i = 0; i < scene_.count(); ++i) {
            if (i > 0)
                vkCmdPipelineBarrier(commandBuffer, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
            vkCmdDispatch(commandBuffer, 1, 1, 1);
        }
        commands_.submitAndWait();
    }

private:
    const DispatchScene& scene_;
    RawVulkanCommands commands_;
    vulkan::NativePipeline pipeline_;
    RawVulkanDescriptorSet set_;
};

} // namespace

std::unique_ptr<RawFrame> createRawVulkanDraws(rhi::Device& device, const DrawScene& scene, DrawCall call)
{
    return std::make_unique<RawVulkanDraws>(device, scene, call);
}

std::unique_ptr<RawFrame> createRawVulkanDispatches(rhi::Device& device, const DispatchScene& scene)
{
    return std::make_unique<RawVulkanDispatches>(device, scene);
}

} // namespace penumbra::apps
