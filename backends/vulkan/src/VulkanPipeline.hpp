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

// One descriptor-set layout and pipeline layout per distinct binding list and stages. Pipelines with the same
// bindings share them, so switching between such pipelines keeps the bound descriptor set valid.
class LayoutCache {
public:
    explicit LayoutCache(VkDevice device) : device_(device) {}

    PipelineLayout get(const std::vector<rhi::ShaderBinding>& bindings, VkShaderStageFlags stages);

private:
    struct Entry {
        UniqueDescriptorSetLayout setLayout;
        UniquePipelineLayout layout; // after setLayout: destroyed before it
    };
    Entry create(const std::vector<rhi::ShaderBinding>& bindings, VkShaderStageFlags stages) const;

    VkDevice device_;
    std::mutex mutex_;
    std::map<std::vector<std::uint32_t>, Entry> layouts_;
};

// What DescriptorBinder needs of a graphics or compute pipeline.
struct DescriptorLayout {
    const std::vector<rhi::ShaderBinding>* bindings = nullptr; // sorted by number
    std::vector<std::uint32_t> uniformBindings; // uniform blocks, in the order of their dynamic offsets
    PipelineLayout layout;
    VkPipelineBindPoint bindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
};

// The descriptor type of a binding kind.
VkDescriptorType descriptorType(rhi::BindingKind kind);

// Binding numbers of the uniform blocks among `bindings`, in order.
std::vector<std::uint32_t> uniformBindingsOf(const std::vector<rhi::ShaderBinding>& bindings);

class VulkanPipeline final : public rhi::Pipeline {
public:
    VulkanPipeline(std::shared_ptr<Context> context, const rhi::PipelineDesc& desc);

    const rhi::PipelineDesc& desc() const override { return desc_; }

    VkPipeline handle() const { return pipeline_.get(); }
    const PipelineLayout& layout() const { return layout_; }
    // Every binding both stages declare, sorted by number: the descriptor set's contents.
    const std::vector<rhi::ShaderBinding>& bindings() const override { return bindings_; }
    const DescriptorLayout& descriptors() const { return descriptors_; }
    // The desc's bias with the sign the conventions give it.
    const rhi::DepthBias& signedBias() const { return signedBias_; }
    // The render pass this pipeline was created against (compatible with matching framebuffers).
    VkRenderPass renderPass() const { return renderPass_; }

private:
    std::shared_ptr<Context> context_;
    rhi::PipelineDesc desc_;
    std::vector<rhi::ShaderBinding> bindings_;
    rhi::DepthBias signedBias_;
    PipelineLayout layout_;
    DescriptorLayout descriptors_;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    UniquePipeline pipeline_;
};

class VulkanComputePipeline final : public rhi::ComputePipeline {
public:
    VulkanComputePipeline(std::shared_ptr<Context> context, const rhi::ComputePipelineDesc& desc);

    const rhi::ComputePipelineDesc& desc() const override { return desc_; }
    VkPipeline handle() const { return pipeline_.get(); }
    const DescriptorLayout& descriptors() const { return descriptors_; }

private:
    std::shared_ptr<Context> context_;
    rhi::ComputePipelineDesc desc_;
    DescriptorLayout descriptors_;
    UniquePipeline pipeline_;
};

} // namespace penumbra::vulkan
