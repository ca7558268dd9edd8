#pragma once

#include "VulkanContext.hpp"

#include "penumbra/rhi/Resources.hpp"

#include <array>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

struct AttachmentKey {
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkImageLayout restingLayout = VK_IMAGE_LAYOUT_UNDEFINED; // initial (when loading) and final layout
    bool load = false; // keep contents instead of clearing
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
};

struct RenderPassKey {
    std::vector<AttachmentKey> colors;
    std::optional<AttachmentKey> depth;
};

// One VkRenderPass per distinct key, alive as long as the device: pipelines and framebuffers
// only need a compatible one, passes need the exact load ops and layouts.
class RenderPassCache {
public:
    explicit RenderPassCache(VkDevice device) : device_(device) {}

    VkRenderPass get(const RenderPassKey& key);

private:
    UniqueRenderPass create(const RenderPassKey& key) const;

    VkDevice device_;
    std::mutex mutex_;
    std::map<std::vector<std::uint32_t>, UniqueRenderPass> passes_;
};

class VulkanFramebuffer final : public rhi::Framebuffer {
public:
    VulkanFramebuffer(std::shared_ptr<Context> context, const rhi::FramebufferDesc& desc);

    std::uint32_t width() const override { return width_; }
    std::uint32_t height() const override { return height_; }
    const rhi::AttachmentFormats& formats() const override { return formats_; }

    VkFramebuffer handle() const { return framebuffer_.get(); }
    std::uint32_t colorCount() const { return std::uint32_t(key_.colors.size()); }
    bool hasDepth() const { return key_.depth.has_value(); }
    const std::string& name() const { return name_; }
    // The render pass for a pass that loads or clears colour and depth.
    VkRenderPass renderPass(bool loadColor, bool loadDepth) const;

private:
    std::shared_ptr<Context> context_;
    rhi::AttachmentFormats formats_;
    RenderPassKey key_;
    std::string name_;
    std::uint32_t width_ = 0;
    std::uint32_t height_ = 0;
    std::vector<UniqueImageView> views_;
    UniqueFramebuffer framebuffer_;
    std::array<VkRenderPass, 4> passes_{}; // indexed by loadColor * 2 + loadDepth
};

} // namespace penumbra::vulkan
