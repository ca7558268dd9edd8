#include "VulkanRenderPass.hpp"

#include "VulkanCheck.hpp"
#include "VulkanResources.hpp"

#include "penumbra/rhi/BackendSupport.hpp"
#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::vulkan {
namespace {

std::vector<std::uint32_t> flatten(const RenderPassKey& key)
{
    std::vector<std::uint32_t> flat;
    auto add = [&](const AttachmentKey& a) {
        flat.insert(flat.end(), {std::uint32_t(a.format), std::uint32_t(a.restingLayout), std::uint32_t(a.load),
                                 std::uint32_t(a.samples)});
    };
    for (const AttachmentKey& c : key.colors)
        add(c);
    flat.push_back(key.depth ? 1u : 0u); // separates a depth attachment from one more colour
    if (key.depth)
        add(*key.depth);
    return flat;
}

VkAttachmentDescription describeAttachment(const AttachmentKey& a)
{
    VkAttachmentDescription d{};
    d.format = a.format;
    d.samples = a.samples;
    d.loadOp = a.load ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
    d.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    d.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    d.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    // Cleared contents are not needed, so the first transition may discard them.
    d.initialLayout = a.load ? a.restingLayout : VK_IMAGE_LAYOUT_UNDEFINED;
    d.finalLayout = a.restingLayout;
    return d;
}

AttachmentKey attachmentKey(const rhi::Attachment& attachment)
{
    const auto* texture = dynamic_cast<const VulkanTexture*>(attachment.texture);
    if (!texture)
        throw rhi::Error(fmt::format("framebuffer: texture '{}' was not created by a Vulkan device",
                                     attachment.texture->desc().debugName));
    return {texture->format(), texture->restingLayout(), false, VkSampleCountFlagBits(texture->desc().samples)};
}

} // namespace

VkRenderPass RenderPassCache::get(const RenderPassKey& key)
{
    std::vector<std::uint32_t> flat = flatten(key);
    std::lock_guard lock(mutex_);
    auto found = passes_.find(flat);
    if (found != passes_.end())
        return found->second.get();
    return passes_.emplace(std::move(flat), create(key)).first->second.get();
}

UniqueRenderPass RenderPassCache::create(const RenderPassKey& key) const
{
    std::vector<VkAttachmentDescription> attachments;
    std::vector<VkAttachmentReference> colorRefs;
    for (const AttachmentKey& c : key.colors) {
        colorRefs.push_back({std::uint32_t(attachments.size()), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
        attachments.push_back(describeAttachment(c));
    }
    const VkAttachmentReference depthRef{std::uint32_t(attachments.size()),
                                         VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    if (key.depth)
        attachments.push_back(describeAttachment(*key.depth));

    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = std::uint32_t(colorRefs.size());
    subpass.pColorAttachments = colorRefs.data();
    subpass.pDepthStencilAttachment = key.depth ? &depthRef : nullptr;

    // Dependencies on both sides over graphics and copies: whatever pass or copy came before is finished and
    // visible, and whatever pass or copy comes after sees this pass's writes. Compute is left out: the RHI's hazard
    // tracker (rhi/Hazards.hpp) orders dispatches against passes with barriers narrowed to what each one uses.
    const VkAccessFlags all = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    const VkPipelineStageFlags graphicsAndCopies = VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    const std::array<VkSubpassDependency, 2> dependencies{{
        {VK_SUBPASS_EXTERNAL, 0, graphicsAndCopies, VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT, all, all, 0},
        {0, VK_SUBPASS_EXTERNAL, VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT, graphicsAndCopies, all, all, 0},
    }};

    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = std::uint32_t(attachments.size());
    info.pAttachments = attachments.data();
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = std::uint32_t(dependencies.size());
    info.pDependencies = dependencies.data();
    return createOwned<UniqueRenderPass>(device_, vkCreateRenderPass, info, "vkCreateRenderPass");
}

VulkanFramebuffer::VulkanFramebuffer(std::shared_ptr<Context> context, const rhi::FramebufferDesc& desc)
    : context_(std::move(context)), formats_(rhi::attachmentFormats(desc))
{
    std::vector<rhi::Attachment> attachments(desc.colors.begin(), desc.colors.end());
    for (const rhi::Attachment& c : desc.colors)
        key_.colors.push_back(attachmentKey(c));
    if (desc.depth.texture) {
        key_.depth = attachmentKey(desc.depth);
        attachments.push_back(desc.depth);
    }
    name_ = desc.debugName;
    width_ = attachments.front().texture->desc().width;
    height_ = attachments.front().texture->desc().height;

    std::vector<VkImageView> views;
    for (const rhi::Attachment& a : attachments)
        views.push_back(
            views_.emplace_back(static_cast<const VulkanTexture*>(a.texture)->createAttachmentView(a.layer)).get());
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    // All four load variants up front: beginPass may run on several recording threads at once (rhi::Device's
    // threading contract), so nothing here is filled lazily.
    for (std::size_t variant = 0; variant < passes_.size(); ++variant) {
        RenderPassKey key = key_;
        for (AttachmentKey& c : key.colors)
            c.load = variant >= 2;
        if (key.depth)
            key.depth->load = variant % 2 == 1;
        passes_[variant] = context_->renderPasses().get(key);
    }
    info.renderPass = renderPass(false, false);
    info.attachmentCount = std::uint32_t(views.size());
    info.pAttachments = views.data();
    info.width = width_;
    info.height = height_;
    info.layers = 1;
    framebuffer_ = createOwned<UniqueFramebuffer>(context_->device, vkCreateFramebuffer, info, "vkCreateFramebuffer");
    context_->setName(VK_OBJECT_TYPE_FRAMEBUFFER, framebuffer_.get(), desc.debugName);
}

VkRenderPass VulkanFramebuffer::renderPass(bool loadColor, bool loadDepth) const
{
    return passes_[std::size_t(loadColor) * 2 + std::size_t(loadDepth)];
}

} // namespace penumbra::vulkan
