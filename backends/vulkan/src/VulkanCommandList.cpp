#include "VulkanCommandList.hpp"

#include "VulkanCheck.hpp"
#include "VulkanFormats.hpp"
#include "VulkanPipeline.hpp"
#include "VulkanRenderPass.hpp"
#include "VulkanResources.hpp"

#include "penumbra/rhi/BackendSupport.hpp"
#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <array>
#include <fmt/format.h>

namespace penumbra::vulkan {

VulkanCommandList::VulkanCommandList(std::shared_ptr<Context> context)
    : context_(std::move(context)), descriptors_(context_)
{
    const VkDevice device = context_->device;
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.queueFamilyIndex = context_->queueFamily;
    pool_ = createOwned<UniqueCommandPool>(device, vkCreateCommandPool, poolInfo, "vkCreateCommandPool");
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool_.get();
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(device, &alloc, &commands_), "vkAllocateCommandBuffers");
    check(vkAllocateCommandBuffers(device, &alloc, &prologue_), "vkAllocateCommandBuffers");
    const VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fence_ = createOwned<UniqueFence>(device, vkCreateFence, fenceInfo, "vkCreateFence");
    begin();
}

void VulkanCommandList::begin()
{
    VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(commands_, &info), "vkBeginCommandBuffer");
}

void VulkanCommandList::beginPrologue()
{
    VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(prologue_, &info), "vkBeginCommandBuffer");
    prologueRecording_ = true;
}

void VulkanCommandList::submit()
{
    if (inPass_)
        throw rhi::Error("submit: the command list is inside a pass; call endPass() first");
    std::array<VkCommandBuffer, 2> buffers{};
    std::size_t count = 0;
    if (prologueRecording_) {
        check(vkEndCommandBuffer(prologue_), "vkEndCommandBuffer");
        buffers[count++] = prologue_;
    }
    check(vkEndCommandBuffer(commands_), "vkEndCommandBuffer");
    buffers[count++] = commands_;
    context_->submitAndWait(std::span(buffers.data(), count), fence_.get());

    check(vkResetCommandPool(context_->device, pool_.get(), 0), "vkResetCommandPool");
    prologueRecording_ = false;
    resetPools_.clear();
    descriptors_.reset();
    pipeline_ = nullptr;
    begin();
}

void VulkanCommandList::requireDraw(std::string_view what) const
{
    if (!inPass_ || !pipeline_)
        throw rhi::Error(fmt::format("{}: needs {} first", what, inPass_ ? "bindPipeline()" : "beginPass()"));
    if (!pipelineFitsPass_)
        throw rhi::Error(fmt::format("{}: pipeline '{}' renders to other attachment formats than framebuffer '{}' has",
                                     what, pipeline_->desc().debugName, passName_));
}

void VulkanCommandList::requireOutsidePass(std::string_view what) const
{
    if (inPass_)
        throw rhi::Error(fmt::format("{}: not allowed inside a pass; call endPass() first", what));
}

void VulkanCommandList::matchPipelineToPass()
{
    pipelineFitsPass_ = inPass_ && pipeline_ && pipeline_->formats() == *passFormats_;
}

void VulkanCommandList::beginPass(const rhi::PassDesc& pass)
{
    requireOutsidePass("beginPass");
    if (!pass.framebuffer)
        throw rhi::Error("beginPass: PassDesc::framebuffer is null");
    auto& framebuffer = const_cast<VulkanFramebuffer&>(
        vulkanObject<const VulkanFramebuffer>(*pass.framebuffer, "beginPass: the framebuffer"));

    std::vector<VkClearValue> clears(framebuffer.colorCount() + (framebuffer.hasDepth() ? 1 : 0));
    const glm::vec4 color = pass.clearColor.value_or(glm::vec4(0.0f));
    for (std::uint32_t i = 0; i < framebuffer.colorCount(); ++i)
        clears[i].color = {{color.r, color.g, color.b, color.a}};
    if (framebuffer.hasDepth())
        clears.back().depthStencil = {context_->conventions.clearDepth(), 0};

    VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    info.renderPass = framebuffer.renderPass(!pass.clearColor.has_value(), !pass.clearDepth);
    info.framebuffer = framebuffer.handle();
    info.renderArea = {{0, 0}, {framebuffer.width(), framebuffer.height()}};
    info.clearValueCount = std::uint32_t(clears.size());
    info.pClearValues = clears.data();
    vkCmdBeginRenderPass(commands_, &info, VK_SUBPASS_CONTENTS_INLINE);
    inPass_ = true;
    passFormats_ = &framebuffer.formats();
    passName_ = framebuffer.name();
    matchPipelineToPass();

    setViewport({0.0f, 0.0f, float(framebuffer.width()), float(framebuffer.height())});
    setScissor({0, 0, framebuffer.width(), framebuffer.height()});
}

void VulkanCommandList::endPass()
{
    if (!inPass_)
        throw rhi::Error("endPass: no pass is open");
    vkCmdEndRenderPass(commands_);
    inPass_ = false;
}

void VulkanCommandList::setViewport(const rhi::Viewport& v)
{
    // Negative height (core since 1.1) puts NDC +y on row 0, the top: the library's convention.
    const VkViewport viewport{v.x, v.y + v.height, v.width, -v.height, 0.0f, 1.0f};
    vkCmdSetViewport(commands_, 0, 1, &viewport);
}

void VulkanCommandList::setScissor(const rhi::Rect& r)
{
    // Vulkan refuses negative offsets; the part left of or above the target is empty anyway.
    const std::int32_t x = std::max(r.x, 0);
    const std::int32_t y = std::max(r.y, 0);
    const auto shrink = [](std::uint32_t extent, std::int32_t cut) {
        return std::uint32_t(std::max<std::int64_t>(0, std::int64_t(extent) - cut));
    };
    const VkRect2D scissor{{x, y}, {shrink(r.width, x - r.x), shrink(r.height, y - r.y)}};
    vkCmdSetScissor(commands_, 0, 1, &scissor);
}

void VulkanCommandList::setDepthBias(const rhi::DepthBias& bias)
{
    if (bias.clamp != 0.0f && !context_->capabilities.depthBiasClamp)
        throw rhi::UnsupportedError(
            fmt::format("setDepthBias: depth bias clamp is not supported by {}", context_->capabilities.device));
    const rhi::DepthBias b = rhi::signedDepthBias(context_->conventions, bias);
    vkCmdSetDepthBias(commands_, b.constant, b.clamp, b.slope);
}

void VulkanCommandList::bindPipeline(const rhi::Pipeline& pipeline)
{
    pipeline_ = &vulkanObject<const VulkanPipeline>(pipeline, "bindPipeline: the pipeline");
    matchPipelineToPass();
    vkCmdBindPipeline(commands_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_->handle());
    const rhi::DepthBias& b = pipeline_->signedBias();
    vkCmdSetDepthBias(commands_, b.constant, b.clamp, b.slope);
    descriptors_.setPipeline(*pipeline_);
}

void VulkanCommandList::bindVertexBuffer(std::uint32_t slot, const rhi::Buffer& buffer, std::uint64_t offset)
{
    const VkBuffer handle = vulkanObject<const VulkanBuffer>(buffer, "bindVertexBuffer: the buffer").handle();
    vkCmdBindVertexBuffers(commands_, slot, 1, &handle, &offset);
}

void VulkanCommandList::bindIndexBuffer(const rhi::Buffer& buffer, rhi::IndexType type, std::uint64_t offset)
{
    const VkBuffer handle = vulkanObject<const VulkanBuffer>(buffer, "bindIndexBuffer: the buffer").handle();
    vkCmdBindIndexBuffer(commands_, handle, offset, toVkIndexType(type));
}

void VulkanCommandList::bindUniformBuffer(std::uint32_t binding, const rhi::Buffer& buffer, std::uint64_t offset,
                                          std::uint64_t size)
{
    const auto& vk = vulkanObject<const VulkanBuffer>(buffer, "bindUniformBuffer: the buffer");
    // Vulkan guarantees a power-of-two alignment, so a mask tests it.
    const std::uint64_t total = vk.desc().size;
    if (size == 0 || size > context_->properties.limits.maxUniformBufferRange || offset > total || size > total - offset || (offset & (context_->capabilities.uniformBufferOffsetAlignment - 1)) ||
        offset > UINT32_MAX)
        throw rhi::Error(fmt::format("bindUniformBuffer {}: {} bytes at offset {} of buffer '{}' ({} bytes); offsets "
                                     "must be multiples of {} and sizes at most {}",
                                     binding, size, offset, vk.desc().debugName, total,
                                     context_->capabilities.uniformBufferOffsetAlignment,
                                     context_->properties.limits.maxUniformBufferRange));
    descriptors_.setUniformBuffer(binding, vk.handle(), std::uint32_t(offset), size);
}

void VulkanCommandList::bindTexture(std::uint32_t binding, const rhi::Texture& texture, const rhi::Sampler& sampler)
{
    const auto& vkTexture = vulkanObject<const VulkanTexture>(texture, "bindTexture: the texture");
    const auto& vkSampler = vulkanObject<const VulkanSampler>(sampler, "bindTexture: the sampler");
    if (!rhi::hasFlag(texture.desc().usage, rhi::TextureUsage::Sampled))
        throw rhi::Error(fmt::format("bindTexture {}: texture '{}' lacks TextureUsage::Sampled", binding,
                                     texture.desc().debugName));
    rhi::checkTextureBinding(context_->capabilities, texture, sampler);
    descriptors_.setTexture(binding, vkTexture.sampledView(), vkSampler.handle());
}

void VulkanCommandList::draw(std::uint32_t vertexCount, std::uint32_t instanceCount, std::uint32_t firstVertex,
                             std::uint32_t firstInstance)
{
    requireDraw("draw");
    descriptors_.flush(commands_);
    vkCmdDraw(commands_, vertexCount, instanceCount, firstVertex, firstInstance);
}

void VulkanCommandList::drawIndexed(std::uint32_t indexCount, std::uint32_t instanceCount, std::uint32_t firstIndex,
                                    std::int32_t vertexOffset, std::uint32_t firstInstance)
{
    requireDraw("drawIndexed");
    descriptors_.flush(commands_);
    vkCmdDrawIndexed(commands_, indexCount, instanceCount, firstIndex, vertexOffset, firstInstance);
}

void VulkanCommandList::writeTimestamp(rhi::TimestampQueries& queries, std::uint32_t index)
{
    const auto& vk = vulkanObject<const VulkanTimestampQueries>(queries, "writeTimestamp: the queries");
    if (index >= vk.count())
        throw rhi::Error(fmt::format("writeTimestamp: index {} is out of range [0, {}]", index, vk.count() - 1));
    // Reset once per submission, in the prologue that runs before this list's commands.
    if (std::find(resetPools_.begin(), resetPools_.end(), vk.handle()) == resetPools_.end()) {
        if (!prologueRecording_)
            beginPrologue();
        vkCmdResetQueryPool(prologue_, vk.handle(), 0, vk.count());
        resetPools_.push_back(vk.handle());
    }
    vkCmdWriteTimestamp(commands_, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, vk.handle(), index);
}

} // namespace penumbra::vulkan
