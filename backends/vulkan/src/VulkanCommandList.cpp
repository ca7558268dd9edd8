#include "VulkanCommandList.hpp"

#include "VulkanBindingSet.hpp"
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

VulkanCommandList::VulkanCommandList(rhi::ValidatingDevice& owner, std::shared_ptr<Context> context)
    : ValidatingCommandList(owner), context_(std::move(context)), descriptors_(context_), computeDescriptors_(context_),
      drawCounts_(context_)
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
    computeDescriptors_.reset();
    drawCounts_.reset();
    pipeline_ = nullptr;
    framebuffer_ = nullptr;
    computePipeline_ = VK_NULL_HANDLE;
    begin();
}

void VulkanCommandList::apiBeginPass(const rhi::PassDesc& pass)
{
    const auto& framebuffer = vulkanObject<const VulkanFramebuffer>(*pass.framebuffer, "beginPass: the framebuffer");

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
    framebuffer_ = &framebuffer;
    apiSetViewport({0.0f, 0.0f, float(framebuffer.width()), float(framebuffer.height())});
    apiSetScissor({0, 0, framebuffer.width(), framebuffer.height()});
}

void VulkanCommandList::apiEndPass() { vkCmdEndRenderPass(commands_); }

void VulkanCommandList::apiSetViewport(const rhi::Viewport& v)
{
    // Negative height (core since 1.1) puts NDC +y on row 0, the top: the library's convention.
    const VkViewport viewport{v.x, v.y + v.height, v.width, -v.height, 0.0f, 1.0f};
    vkCmdSetViewport(commands_, 0, 1, &viewport);
}

void VulkanCommandList::apiSetScissor(const rhi::Rect& r)
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

void VulkanCommandList::apiSetDepthBias(const rhi::DepthBias& bias)
{
    const rhi::DepthBias b = rhi::signedDepthBias(context_->conventions, bias);
    vkCmdSetDepthBias(commands_, b.constant, b.clamp, b.slope);
}

void VulkanCommandList::apiBindPipeline(const rhi::Pipeline& pipeline)
{
    pipeline_ = &vulkanObject<const VulkanPipeline>(pipeline, "bindPipeline: the pipeline");
    vkCmdBindPipeline(commands_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_->handle());
    const rhi::DepthBias& b = pipeline_->signedBias();
    vkCmdSetDepthBias(commands_, b.constant, b.clamp, b.slope);
    descriptors_.setPipeline(pipeline_->descriptors());
}

void VulkanCommandList::apiBindComputePipeline(const rhi::ComputePipeline& pipeline)
{
    const auto& vk = vulkanObject<const VulkanComputePipeline>(pipeline, "bindComputePipeline: the pipeline");
    vkCmdBindPipeline(commands_, VK_PIPELINE_BIND_POINT_COMPUTE, vk.handle());
    computePipeline_ = vk.handle();
    computeDescriptors_.setPipeline(vk.descriptors());
}

void VulkanCommandList::apiBindVertexBuffer(std::uint32_t slot, const rhi::Buffer& buffer, std::uint64_t offset)
{
    const VkBuffer handle = vulkanObject<const VulkanBuffer>(buffer, "bindVertexBuffer: the buffer").handle();
    vkCmdBindVertexBuffers(commands_, slot, 1, &handle, &offset);
}

void VulkanCommandList::apiBindIndexBuffer(const rhi::Buffer& buffer, rhi::IndexType type, std::uint64_t offset)
{
    const VkBuffer handle = vulkanObject<const VulkanBuffer>(buffer, "bindIndexBuffer: the buffer").handle();
    vkCmdBindIndexBuffer(commands_, handle, offset, toVkIndexType(type));
}

void VulkanCommandList::bindSingle(const rhi::BindingSetItem& item, std::string_view what)
{
    const Descriptor descriptor = describe(item, what);
    descriptors_.set(item.binding, descriptor);
    computeDescriptors_.set(item.binding, descriptor);
}

namespace {

// Dynamic offsets are 32-bit (vkCmdBindDescriptorSets' pDynamicOffsets).
void checkDynamicOffset(std::string_view what, std::uint64_t offset)
{
    if (offset > UINT32_MAX)
        throw rhi::UnsupportedError(fmt::format("{}: offset {} exceeds Vulkan's 32-bit dynamic offsets", what, offset));
}

} // namespace

void VulkanCommandList::apiBindUniformBuffer(std::uint32_t binding, const rhi::Buffer& buffer, std::uint64_t offset,
                                             std::uint64_t size)
{
    checkDynamicOffset("bindUniformBuffer", offset);
    bindSingle(rhi::BindingSetItem::uniformBuffer(binding, buffer, offset, size), "bindUniformBuffer");
}

void VulkanCommandList::apiBindStorageBuffer(std::uint32_t binding, const rhi::Buffer& buffer, std::uint64_t offset,
                                             std::uint64_t size)
{
    bindSingle(rhi::BindingSetItem::storageBuffer(binding, buffer, offset, size), "bindStorageBuffer");
}

void VulkanCommandList::apiBindStorageTexture(std::uint32_t binding, const rhi::Texture& texture, std::uint32_t level)
{
    bindSingle(rhi::BindingSetItem::storageTexture(binding, texture, level), "bindStorageTexture");
}

void VulkanCommandList::apiBindTexture(std::uint32_t binding, const rhi::Texture& texture, const rhi::Sampler& sampler)
{
    bindSingle(rhi::BindingSetItem::sampledTexture(binding, texture, sampler), "bindTexture");
}

void VulkanCommandList::apiBindBindingSet(const rhi::BindingSet& set)
{
    const auto& vk = vulkanObject<const VulkanBindingSet>(set, "bindBindingSet: the set");
    // A pipeline that does not list the set's layout binds its uniform ranges per draw, with dynamic offsets.
    for (const rhi::BindingSetItem& item : set.items())
        if (item.kind == rhi::BindingKind::UniformBuffer)
            checkDynamicOffset("bindBindingSet", item.offset);
    descriptors_.setBindingSet(vk);
    computeDescriptors_.setBindingSet(vk);
}

DescriptorCounts VulkanCommandList::descriptorCounts() const
{
    DescriptorCounts sum;
    for (const DescriptorBinder* binder : {&descriptors_, &computeDescriptors_}) {
        sum.bindCalls += binder->counts().bindCalls;
        sum.bindingSetBinds += binder->counts().bindingSetBinds;
        sum.setsWritten += binder->counts().setsWritten;
    }
    return sum;
}

void VulkanCommandList::apiDraw(std::uint32_t vertexCount, std::uint32_t instanceCount, std::uint32_t firstVertex,
                                std::uint32_t firstInstance)
{
    descriptors_.flush(commands_);
    vkCmdDraw(commands_, vertexCount, instanceCount, firstVertex, firstInstance);
}

void VulkanCommandList::apiDrawIndexed(std::uint32_t indexCount, std::uint32_t instanceCount, std::uint32_t firstIndex,
                                       std::int32_t vertexOffset, std::uint32_t firstInstance)
{
    descriptors_.flush(commands_);
    vkCmdDrawIndexed(commands_, indexCount, instanceCount, firstIndex, vertexOffset, firstInstance);
}

void VulkanCommandList::apiDrawIndirect(const rhi::Buffer& buffer, std::uint64_t offset)
{
    descriptors_.flush(commands_);
    const VkBuffer handle = vulkanObject<const VulkanBuffer>(buffer, "drawIndirect: the buffer").handle();
    vkCmdDrawIndirect(commands_, handle, offset, 1, 0);
}

void VulkanCommandList::apiDrawIndexedIndirect(const rhi::Buffer& buffer, std::uint64_t offset)
{
    descriptors_.flush(commands_);
    const VkBuffer handle = vulkanObject<const VulkanBuffer>(buffer, "drawIndexedIndirect: the buffer").handle();
    vkCmdDrawIndexedIndirect(commands_, handle, offset, 1, 0);
}

void VulkanCommandList::apiDrawIndirectCount(const rhi::Buffer& buffer, std::uint64_t offset, const rhi::Buffer& count,
                                             std::uint64_t countOffset, std::uint32_t maxDrawCount)
{
    drawCount(buffer, offset, count, countOffset, maxDrawCount, false);
}

void VulkanCommandList::apiDrawIndexedIndirectCount(const rhi::Buffer& buffer, std::uint64_t offset,
                                                    const rhi::Buffer& count, std::uint64_t countOffset,
                                                    std::uint32_t maxDrawCount)
{
    drawCount(buffer, offset, count, countOffset, maxDrawCount, true);
}

void VulkanCommandList::drawCount(const rhi::Buffer& buffer, std::uint64_t offset, const rhi::Buffer& count,
                                  std::uint64_t countOffset, std::uint32_t maxDrawCount, bool indexed)
{
    const auto& arguments = vulkanObject<const VulkanBuffer>(buffer, "drawIndirectCount: the buffer");
    const auto& counter = vulkanObject<const VulkanBuffer>(count, "drawIndirectCount: the count buffer");
    const std::uint32_t stride = indexed ? rhi::kDrawIndexedIndirectCommandBytes : rhi::kDrawIndirectCommandBytes;
    if (context_->drawIndirectCount) {
        descriptors_.flush(commands_);
        (indexed ? context_->drawIndexedIndirectCount : context_->drawIndirectCount)(commands_, arguments.handle(),
                                                                                     offset, counter.handle(),
                                                                                     countOffset, maxDrawCount, stride);
        return;
    }
    if (maxDrawCount == 0)
        return;
    // Suspended: bound pipelines, descriptor sets, vertex and index buffers and dynamic state (viewport, scissor,
    // depth bias) are command buffer state, which render pass instances do not reset (Vulkan 1.3 section 6.1).
    vkCmdEndRenderPass(commands_);
    const VkBuffer patched =
        drawCounts_.patch(commands_, arguments, offset, counter, countOffset, maxDrawCount, stride / 4);
    if (computePipeline_ != VK_NULL_HANDLE)
        vkCmdBindPipeline(commands_, VK_PIPELINE_BIND_POINT_COMPUTE, computePipeline_);
    computeDescriptors_.rebind();
    VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    info.renderPass = framebuffer_->renderPass(true, true);
    info.framebuffer = framebuffer_->handle();
    info.renderArea = {{0, 0}, {framebuffer_->width(), framebuffer_->height()}};
    vkCmdBeginRenderPass(commands_, &info, VK_SUBPASS_CONTENTS_INLINE);
    descriptors_.flush(commands_);
    // Without multiDrawIndirect, one command per draw.
    const std::uint32_t perDraw = context_->multiDrawIndirect ? maxDrawCount : 1;
    for (std::uint32_t first = 0; first < maxDrawCount; first += perDraw) {
        const VkDeviceSize at = DrawCountEmulation::commandsOffset + VkDeviceSize(first) * stride;
        if (indexed)
            vkCmdDrawIndexedIndirect(commands_, patched, at, perDraw, stride);
        else
            vkCmdDrawIndirect(commands_, patched, at, perDraw, stride);
    }
}

void VulkanCommandList::apiDispatch(std::uint32_t x, std::uint32_t y, std::uint32_t z)
{
    computeDescriptors_.flush(commands_);
    vkCmdDispatch(commands_, x, y, z);
}

void VulkanCommandList::apiDispatchIndirect(const rhi::Buffer& buffer, std::uint64_t offset)
{
    computeDescriptors_.flush(commands_);
    const VkBuffer handle = vulkanObject<const VulkanBuffer>(buffer, "dispatchIndirect: the buffer").handle();
    vkCmdDispatchIndirect(commands_, handle, offset);
}

void VulkanCommandList::apiBarrier(const rhi::Barrier& barrier)
{
    // One global memory barrier: Khronos' synchronization guidance prefers it to per-resource barriers where no
    // layout or queue changes (the RHI's storage images rest in GENERAL).
    VkMemoryBarrier memory{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    memory.srcAccessMask = toVkAccess(barrier.src.access);
    memory.dstAccessMask = toVkAccess(barrier.dst.access);
    vkCmdPipelineBarrier(commands_, toVkStages(barrier.src.stages), toVkStages(barrier.dst.stages), 0, 1, &memory, 0,
                         nullptr, 0, nullptr);
}

void VulkanCommandList::apiWriteTimestamp(rhi::TimestampQueries& queries, std::uint32_t index)
{
    const auto& vk = vulkanObject<const VulkanTimestampQueries>(queries, "writeTimestamp: the queries");
    // Reset once per submission, in the prologue that runs before this list's commands.
    if (std::find(resetPools_.begin(), resetPools_.end(), vk.handle()) == resetPools_.end()) {
        if (!prologueRecording_)
            beginPrologue();
        vkCmdResetQueryPool(prologue_, vk.handle(), 0, vk.count());
        resetPools_.push_back(vk.handle());
    }
    vkCmdWriteTimestamp(commands_, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, vk.handle(), index);
}

void VulkanCommandList::apiPushLabel(std::string_view name)
{
    if (!context_->beginLabel)
        return;
    const std::string text(name);
    VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
    label.pLabelName = text.c_str();
    context_->beginLabel(commands_, &label);
}

void VulkanCommandList::apiInsertLabel(std::string_view name)
{
    if (!context_->insertLabel)
        return;
    const std::string text(name);
    VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
    label.pLabelName = text.c_str();
    context_->insertLabel(commands_, &label);
}

void VulkanCommandList::apiPopLabel()
{
    if (context_->endLabel)
        context_->endLabel(commands_);
}

} // namespace penumbra::vulkan
