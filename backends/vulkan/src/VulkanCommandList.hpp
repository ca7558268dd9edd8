#pragma once

#include "VulkanContext.hpp"
#include "VulkanDescriptors.hpp"

#include "penumbra/rhi/CommandList.hpp"

#include <vector>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

class VulkanPipeline;

// Records into a VkCommandBuffer from creation on; submit() runs it and starts a new recording.
// Query-pool resets go into a separate prologue buffer, because they are not allowed inside passes.
class VulkanCommandList final : public rhi::CommandList {
public:
    explicit VulkanCommandList(std::shared_ptr<Context> context);

    void beginPass(const rhi::PassDesc& pass) override;
    void endPass() override;
    void setViewport(const rhi::Viewport& viewport) override;
    void setScissor(const rhi::Rect& scissor) override;
    void setDepthBias(const rhi::DepthBias& bias) override;
    void bindPipeline(const rhi::Pipeline& pipeline) override;
    void bindVertexBuffer(std::uint32_t slot, const rhi::Buffer& buffer, std::uint64_t offset) override;
    void bindIndexBuffer(const rhi::Buffer& buffer, rhi::IndexType type, std::uint64_t offset) override;
    void bindUniformBuffer(std::uint32_t binding, const rhi::Buffer& buffer, std::uint64_t offset,
                           std::uint64_t size) override;
    void bindTexture(std::uint32_t binding, const rhi::Texture& texture, const rhi::Sampler& sampler) override;
    void draw(std::uint32_t vertexCount, std::uint32_t instanceCount, std::uint32_t firstVertex,
              std::uint32_t firstInstance) override;
    void drawIndexed(std::uint32_t indexCount, std::uint32_t instanceCount, std::uint32_t firstIndex,
                     std::int32_t vertexOffset, std::uint32_t firstInstance) override;
    void copyBuffer(const rhi::Buffer& src, std::uint64_t srcOffset, rhi::Buffer& dst, std::uint64_t dstOffset,
                    std::uint64_t size) override;
    void copyTexture(const rhi::Texture& src, std::uint32_t srcLayer, rhi::Texture& dst,
                     std::uint32_t dstLayer) override;
    void copyTextureToBuffer(const rhi::Texture& src, std::uint32_t layer, rhi::Buffer& dst,
                             std::uint64_t dstOffset) override;
    void writeTimestamp(rhi::TimestampQueries& queries, std::uint32_t index) override;

    // Ends recording, runs the prologue and the commands, waits, and begins recording anew.
    void submit();
    VkCommandBuffer commandBuffer() const { return commands_; }

private:
    void begin();
    void beginPrologue();
    void requireDraw(std::string_view what) const;
    void requireOutsidePass(std::string_view what) const;
    // Draws need a pipeline made for the open pass's attachment formats; checked once per change.
    void matchPipelineToPass();

    std::shared_ptr<Context> context_;
    UniqueCommandPool pool_; // destroying it frees both command buffers
    VkCommandBuffer commands_ = VK_NULL_HANDLE;
    VkCommandBuffer prologue_ = VK_NULL_HANDLE;
    UniqueFence fence_;
    bool prologueRecording_ = false;
    std::vector<VkQueryPool> resetPools_;
    DescriptorBinder descriptors_;
    const VulkanPipeline* pipeline_ = nullptr;
    bool inPass_ = false;
    const std::vector<VkFormat>* passFormats_ = nullptr; // of the open pass's framebuffer
    std::string_view passName_;
    bool pipelineFitsPass_ = false;
};

} // namespace penumbra::vulkan
