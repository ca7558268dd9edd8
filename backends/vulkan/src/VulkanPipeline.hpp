#pragma once

#include "VulkanContext.hpp"
#include "VulkanLayouts.hpp"

#include "penumbra/rhi/Pipeline.hpp"
#include "penumbra/rhi/Shader.hpp"

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

class VulkanPipeline final : public rhi::Pipeline {
public:
    VulkanPipeline(std::shared_ptr<Context> context, const rhi::PipelineDesc& desc);

    const rhi::PipelineDesc& desc() const override { return desc_; }

    VkPipeline handle() const { return pipeline_.get(); }
    // Every binding both stages declare, sorted by number.
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
