#pragma once

#include "VulkanContext.hpp"

#include "penumbra/rhi/Pipeline.hpp"
#include "penumbra/rhi/Shader.hpp"

#include <map>
#include <mutex>
#include <vector>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

class VulkanShader final : public rhi::Shader {
public:
    VulkanShader(std::shared_ptr<Context> context, rhi::CompiledShader compiled);
    ~VulkanShader() override;
    VulkanShader(const VulkanShader&) = delete;
    VulkanShader& operator=(const VulkanShader&) = delete;

    const rhi::CompiledShader& compiled() const override { return compiled_; }
    VkShaderModule module() const { return module_; }

private:
    std::shared_ptr<Context> context_;
    rhi::CompiledShader compiled_;
    VkShaderModule module_ = VK_NULL_HANDLE;
};

struct PipelineLayout {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
};

// One descriptor-set layout and pipeline layout per distinct binding list. Pipelines with the same
// bindings share them, so switching between such pipelines keeps the bound descriptor set valid.
class LayoutCache {
public:
    explicit LayoutCache(VkDevice device) : device_(device) {}
    ~LayoutCache();
    LayoutCache(const LayoutCache&) = delete;
    LayoutCache& operator=(const LayoutCache&) = delete;

    PipelineLayout get(const std::vector<rhi::ShaderBinding>& bindings);

private:
    PipelineLayout create(const std::vector<rhi::ShaderBinding>& bindings) const;

    VkDevice device_;
    std::mutex mutex_;
    std::map<std::vector<std::uint32_t>, PipelineLayout> layouts_;
};

class VulkanPipeline final : public rhi::Pipeline {
public:
    VulkanPipeline(std::shared_ptr<Context> context, const rhi::PipelineDesc& desc);
    ~VulkanPipeline() override;
    VulkanPipeline(const VulkanPipeline&) = delete;
    VulkanPipeline& operator=(const VulkanPipeline&) = delete;

    const rhi::PipelineDesc& desc() const override { return desc_; }

    VkPipeline handle() const { return pipeline_; }
    const PipelineLayout& layout() const { return layout_; }
    // Every binding both stages declare, sorted by number: the descriptor set's contents.
    const std::vector<rhi::ShaderBinding>& bindings() const { return bindings_; }
    // Binding numbers of the uniform blocks, in the order of their dynamic offsets.
    const std::vector<std::uint32_t>& uniformBindings() const { return uniformBindings_; }
    // The desc's bias with the sign the conventions give it.
    const rhi::DepthBias& signedBias() const { return signedBias_; }
    // The render pass this pipeline was created against (compatible with matching framebuffers).
    VkRenderPass renderPass() const { return renderPass_; }
    // Attachment formats as RenderPassKey::formats() lists them; a framebuffer must match.
    const std::vector<VkFormat>& formats() const { return formats_; }

private:
    std::shared_ptr<Context> context_;
    rhi::PipelineDesc desc_;
    std::vector<rhi::ShaderBinding> bindings_;
    std::vector<std::uint32_t> uniformBindings_;
    rhi::DepthBias signedBias_;
    PipelineLayout layout_;
    std::vector<VkFormat> formats_;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

} // namespace penumbra::vulkan
