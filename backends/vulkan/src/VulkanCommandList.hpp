#pragma once

#include "VulkanContext.hpp"
#include "VulkanDescriptors.hpp"
#include "VulkanDrawCount.hpp"

#include "penumbra/rhi/ValidatingDevice.hpp"

#include <vector>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

class VulkanFramebuffer;
class VulkanPipeline;

// Records into a VkCommandBuffer from creation on; submit() runs it and starts a new recording.
// Query-pool resets go into a separate prologue buffer, because they are not allowed inside passes.
class VulkanCommandList final : public rhi::ValidatingCommandList {
public:
    VulkanCommandList(rhi::ValidatingDevice& owner, std::shared_ptr<Context> context);

    // Ends recording, runs the prologue and the commands, waits, and begins recording anew.
    void submit();
    VkCommandBuffer commandBuffer() const { return commands_; }
    // Both bind points' (penumbra/vulkan/Native.hpp), since the list was created.
    DescriptorCounts descriptorCounts() const;

private:
    void apiBeginPass(const rhi::PassDesc& pass) override;
    void apiEndPass() override;
    void apiSetViewport(const rhi::Viewport& viewport) override;
    void apiSetScissor(const rhi::Rect& scissor) override;
    void apiSetDepthBias(const rhi::DepthBias& bias) override;
    void apiBindPipeline(const rhi::Pipeline& pipeline) override;
    void apiBindVertexBuffer(std::uint32_t slot, const rhi::Buffer& buffer, std::uint64_t offset) override;
    void apiBindIndexBuffer(const rhi::Buffer& buffer, rhi::IndexType type, std::uint64_t offset) override;
    void apiBindUniformBuffer(std::uint32_t binding, const rhi::Buffer& buffer, std::uint64_t offset,
                              std::uint64_t size) override;
    void apiBindTexture(std::uint32_t binding, const rhi::Texture& texture, const rhi::Sampler& sampler) override;
    void apiBindStorageBuffer(std::uint32_t binding, const rhi::Buffer& buffer, std::uint64_t offset,
                              std::uint64_t size) override;
    void apiBindStorageTexture(std::uint32_t binding, const rhi::Texture& texture, std::uint32_t level) override;
    void apiBindBindingSet(const rhi::BindingSet& set) override;
    void apiBindComputePipeline(const rhi::ComputePipeline& pipeline) override;
    void apiDispatch(std::uint32_t x, std::uint32_t y, std::uint32_t z) override;
    void apiDispatchIndirect(const rhi::Buffer& buffer, std::uint64_t offset) override;
    void apiDrawIndirect(const rhi::Buffer& buffer, std::uint64_t offset) override;
    void apiDrawIndexedIndirect(const rhi::Buffer& buffer, std::uint64_t offset) override;
    void apiDrawIndirectCount(const rhi::Buffer& buffer, std::uint64_t offset, const rhi::Buffer& count,
                              std::uint64_t countOffset, std::uint32_t maxDrawCount) override;
    void apiDrawIndexedIndirectCount(const rhi::Buffer& buffer, std::uint64_t offset, const rhi::Buffer& count,
                                     std::uint64_t countOffset, std::uint32_t maxDrawCount) override;
    void apiBarrier(const rhi::Barrier& barrier) override;
    void apiDraw(std::uint32_t vertexCount, std::uint32_t instanceCount, std::uint32_t firstVertex,
                 std::uint32_t firstInstance) override;
    void apiDrawIndexed(std::uint32_t indexCount, std::uint32_t instanceCount, std::uint32_t firstIndex,
                        std::int32_t vertexOffset, std::uint32_t firstInstance) override;
    void apiCopyBuffer(const rhi::Buffer& src, std::uint64_t srcOffset, rhi::Buffer& dst, std::uint64_t dstOffset,
                       std::uint64_t size) override;
    void apiCopyTexture(const rhi::Texture& src, std::uint32_t srcLayer, rhi::Texture& dst,
                        std::uint32_t dstLayer) override;
    void apiCopyTextureToBuffer(const rhi::Texture& src, std::uint32_t layer, std::uint32_t level, rhi::Buffer& dst,
                                std::uint64_t dstOffset) override;
    void apiResolveTexture(const rhi::Texture& src, rhi::Texture& dst) override;
    void apiWriteTimestamp(rhi::TimestampQueries& queries, std::uint32_t index) override;
    void apiPushLabel(std::string_view name) override;
    void apiPopLabel() override;
    void apiInsertLabel(std::string_view name) override;

    void begin();
    void beginPrologue();
    // A single bind call's resource, for both bind points.
    void bindSingle(const rhi::BindingSetItem& item, std::string_view what);
    // Both count draws: the device's own, or the emulation (DrawCountEmulation), which suspends the pass.
    void drawCount(const rhi::Buffer& buffer, std::uint64_t offset, const rhi::Buffer& count, std::uint64_t countOffset,
                   std::uint32_t maxDrawCount, bool indexed);

    std::shared_ptr<Context> context_;
    UniqueCommandPool pool_; // destroying it frees both command buffers
    VkCommandBuffer commands_ = VK_NULL_HANDLE;
    VkCommandBuffer prologue_ = VK_NULL_HANDLE;
    UniqueFence fence_;
    bool prologueRecording_ = false;
    std::vector<VkQueryPool> resetPools_;
    DescriptorBinder descriptors_; // the graphics bind point's
    DescriptorBinder computeDescriptors_;
    const VulkanPipeline* pipeline_ = nullptr;
    const VulkanFramebuffer* framebuffer_ = nullptr; // the open pass's
    VkPipeline computePipeline_ = VK_NULL_HANDLE; // the bound one, restored after an emulated count draw
    DrawCountEmulation drawCounts_;
};

} // namespace penumbra::vulkan
