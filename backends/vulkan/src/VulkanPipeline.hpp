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

    const rhi::CompiledShader& compiled() const override { return compiled_; }
    VkShaderModule module() const { return module_.get(); }

private:
    std::shared_ptr<Context> context_;
    rhi::CompiledShader compiled_;
    UniqueShaderModule module_;
};

// A layout as pipelines and descriptor sets use it; LayoutCache owns the handles.
struct PipelineLayout {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
};

// One descriptor-set layout and pipeline layout per distinct binding list. Pipelines with the same
// bindings share them, so switching between such pipelines keeps the bound descriptor set valid.
class LayoutCache {
public:
    explicit LayoutCache(VkDevice device) : device_(device) {}

    PipelineLayout get(const std::vector<rhi::ShaderBinding>& bindings);

private:
    struct Entry {
        UniqueDescriptorSetLayout setLayout;
        UniquePipelineLayout layout; // after setLayout: destroyed before it
    };
    Entry create(const std::vector<rhi::ShaderBinding>& bindings) const;

    VkDevice device_;
    std::mutex mutex_;
    std::map<std::vector<std::uint32_t>, Entry> layouts_;
};

class VulkanPipeline final : public rhi::Pipeline {
public:
    VulkanPipeline(std::shared_ptr<Context> context, const rhi::PipelineDesc& desc);

    const rhi::PipelineDesc& desc() const override { return desc_; }

    VkPipeline handle() const { return pipeline_.get(); }
    const PipelineLayout& layout() const { return layout_; }
    // Every binding both stages declare, sorted by number: the descriptor set's contents.
    const std::vector<rhi::ShaderBinding>& bindings() const override { return bindings_; }
    // Binding numbers of the uniform blocks, in the order of their dynamic offsets.
    const std::vector<std::uint32_t>& uniformBindings() const { return uniformBindings_; }
    // The desc's bias with the sign the conventions give it.
    const rhi::DepthBias& signedBias() const { return signedBias_; }
    // The render pass this pipeline was created against (compatible with matching framebuffers).
    VkRenderPass renderPass() const { return renderPass_; }

private:
    std::shared_ptr<Context> context_;
    rhi::PipelineDesc desc_;
    std::vector<rhi::ShaderBinding> bindings_;
    std::vector<std::uint32_t> uniformBindings_;
    rhi::DepthBias signedBias_;
    PipelineLayout layout_;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    UniquePipeline pipeline_;
};

} // namespace penumbra::vulkan
