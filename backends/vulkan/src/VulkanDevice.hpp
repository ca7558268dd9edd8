#pragma once

// The rhi::Device of this backend (the public header penumbra/vulkan/VulkanDevice.hpp only has the factory).

#include "VulkanContext.hpp"
#include "VulkanPipelineCache.hpp"
#include "VulkanStaging.hpp"

#include "penumbra/rhi/ValidatingDevice.hpp"

#include <memory>
#include <optional>

namespace penumbra::vulkan {

class VulkanDevice final : public rhi::ValidatingDevice {
public:
    explicit VulkanDevice(const rhi::DeviceDesc& desc);

    const rhi::DeviceDesc& desc() const override { return context_->desc; }
    const rhi::Conventions& conventions() const override { return context_->conventions; }
    const rhi::Capabilities& capabilities() const override { return context_->capabilities; }

    std::unique_ptr<rhi::CommandList> createCommandList() override;
    std::unique_ptr<rhi::Swapchain> createSwapchain() override;
    std::vector<double> readTimestamps(const rhi::TimestampQueries& queries) override;

    std::vector<std::string> debugMessages() const override { return context_->log.all(); }
    void clearDebugMessages() override { context_->log.clear(); }

    const Context& context() const { return *context_; }

private:
    std::unique_ptr<rhi::Buffer> apiCreateBuffer(const rhi::BufferDesc& desc) override;
    std::unique_ptr<rhi::Texture> apiCreateTexture(const rhi::TextureDesc& desc) override;
    void apiWriteTexture(rhi::Texture& texture, std::uint32_t layer, std::uint32_t level,
                         std::span<const std::byte> data) override;
    std::unique_ptr<rhi::Sampler> apiCreateSampler(const rhi::SamplerDesc& desc) override;
    std::unique_ptr<rhi::Shader> apiCreateShader(rhi::CompiledShader compiled) override;
    std::unique_ptr<rhi::Pipeline> apiCreatePipeline(const rhi::PipelineDesc& desc) override;
    std::unique_ptr<rhi::ComputePipeline> apiCreateComputePipeline(const rhi::ComputePipelineDesc& desc) override;
    std::unique_ptr<rhi::BindingSet> apiCreateBindingSet(const rhi::BindingSetDesc& desc) override;
    std::unique_ptr<rhi::Framebuffer> apiCreateFramebuffer(const rhi::FramebufferDesc& desc) override;
    std::unique_ptr<rhi::TimestampQueries> apiCreateTimestampQueries(std::uint32_t count) override;
    void apiSubmit(rhi::CommandList& commands) override;
    // Makes Context::placeholders, once, before a pipeline that lists binding set layouts.
    void makePlaceholders(bool listsLayouts);

    std::shared_ptr<Context> context_;
    StagingBuffer staging_;
    // With DeviceDesc::pipelineCache; declared after context_, so it stores its data before the context can go.
    std::optional<VulkanPipelineCache> pipelineCache_;
    std::unique_ptr<rhi::Buffer> placeholderBuffer_;
    std::unique_ptr<rhi::Texture> placeholderTexture_, placeholderStorage_;
    std::unique_ptr<rhi::Sampler> placeholderSampler_;
};

} // namespace penumbra::vulkan
