#include "VulkanPipeline.hpp"

#include "VulkanCheck.hpp"
#include "VulkanFormats.hpp"
#include "VulkanRenderPass.hpp"
#include "VulkanSpirvSets.hpp"

#include "penumbra/rhi/BackendSupport.hpp"
#include "penumbra/rhi/Error.hpp"

#include <array>
#include <fmt/format.h>

namespace penumbra::vulkan {
namespace {

const VulkanShader& vulkanShader(const rhi::Shader* shader, const rhi::PipelineDesc& desc)
{
    const auto* vk = dynamic_cast<const VulkanShader*>(shader);
    if (!vk)
        throw rhi::Error(fmt::format("pipeline '{}': shader '{}' was not created by a Vulkan device", desc.debugName,
                                     shader->compiled().name));
    return *vk;
}

// A stage's shader module for a pipeline: the shader's own, or with binding set layouts one whose resources are moved
// to their sets (assignDescriptorSets), kept until the pipeline is created.
class StageModule {
public:
    StageModule(const Context& context, const VulkanShader& shader, const DescriptorLayout& layout)
        : module_(shader.module())
    {
        if (layout.sets.empty())
            return;
        const std::vector<std::uint32_t> spirv = assignDescriptorSets(shader.compiled(), layout);
        VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        info.codeSize = spirv.size() * sizeof(std::uint32_t);
        info.pCode = spirv.data();
        placed_ = createOwned<UniqueShaderModule>(context.device, vkCreateShaderModule, info,
                                                  fmt::format("vkCreateShaderModule ({})", shader.compiled().name));
        module_ = placed_.get();
    }

    VkShaderModule module() const { return module_; }

private:
    UniqueShaderModule placed_;
    VkShaderModule module_;
};

RenderPassKey compatibleRenderPass(const rhi::PipelineDesc& desc)
{
    RenderPassKey key;
    const auto samples = VkSampleCountFlagBits(desc.samples);
    for (const rhi::ColorTarget& c : desc.colorTargets)
        key.colors.push_back({toVkFormat(c.format), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, false, samples});
    if (desc.depthFormat)
        key.depth = AttachmentKey{toVkFormat(*desc.depthFormat), VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                                  false, samples};
    return key;
}

VkPipelineColorBlendAttachmentState blendAttachment(const rhi::ColorTarget& target)
{
    const rhi::BlendState& b = target.blend;
    VkPipelineColorBlendAttachmentState state{};
    state.blendEnable = b.enable;
    state.srcColorBlendFactor = toVkBlendFactor(b.srcColor);
    state.dstColorBlendFactor = toVkBlendFactor(b.dstColor);
    state.colorBlendOp = toVkBlendOp(b.colorOp);
    state.srcAlphaBlendFactor = toVkBlendFactor(b.srcAlpha);
    state.dstAlphaBlendFactor = toVkBlendFactor(b.dstAlpha);
    state.alphaBlendOp = toVkBlendOp(b.alphaOp);
    state.colorWriteMask = toVkColorMask(target.writeMask);
    return state;
}

} // namespace

VulkanShader::VulkanShader(std::shared_ptr<Context> context, rhi::CompiledShader compiled)
    : context_(std::move(context)), compiled_(std::move(compiled))
{
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = compiled_.spirv.size() * sizeof(std::uint32_t);
    info.pCode = compiled_.spirv.data();
    module_ = createOwned<UniqueShaderModule>(context_->device, vkCreateShaderModule, info,
                                              fmt::format("vkCreateShaderModule ({})", compiled_.name));
    context_->setName(VK_OBJECT_TYPE_SHADER_MODULE, module_.get(), compiled_.name);
}

VulkanPipeline::VulkanPipeline(std::shared_ptr<Context> context, const rhi::PipelineDesc& desc)
    : context_(std::move(context)), desc_(desc)
{
    bindings_ = rhi::pipelineBindings(desc);
    signedBias_ = rhi::signedDepthBias(context_->conventions, desc.depth.bias);
    descriptors_ =
        describeDescriptors(*context_, desc.debugName, bindings_, desc.bindingSetLayouts,
                            VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, VK_PIPELINE_BIND_POINT_GRAPHICS);
    const RenderPassKey passKey = compatibleRenderPass(desc);
    renderPass_ = context_->renderPasses().get(passKey);

    const StageModule vertex(*context_, vulkanShader(desc.vertex, desc), descriptors_);
    const StageModule fragment(*context_, vulkanShader(desc.fragment, desc), descriptors_);
    const std::array<VkPipelineShaderStageCreateInfo, 2> stages{{
        {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_VERTEX_BIT, vertex.module(),
         "main", nullptr},
        {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_FRAGMENT_BIT,
         fragment.module(), "main", nullptr},
    }};

    std::vector<VkVertexInputBindingDescription> vertexBindings;
    for (std::uint32_t i = 0; i < desc.vertexLayout.buffers.size(); ++i) {
        const rhi::VertexBufferLayout& b = desc.vertexLayout.buffers[i];
        vertexBindings.push_back(
            {i, b.stride, b.perInstance ? VK_VERTEX_INPUT_RATE_INSTANCE : VK_VERTEX_INPUT_RATE_VERTEX});
    }
    std::vector<VkVertexInputAttributeDescription> vertexAttributes;
    for (const rhi::VertexAttribute& a : desc.vertexLayout.attributes)
        vertexAttributes.push_back({a.location, a.buffer, toVkFormat(a.format), a.offset});
    VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertexInput.vertexBindingDescriptionCount = std::uint32_t(vertexBindings.size());
    vertexInput.pVertexBindingDescriptions = vertexBindings.data();
    vertexInput.vertexAttributeDescriptionCount = std::uint32_t(vertexAttributes.size());
    vertexInput.pVertexAttributeDescriptions = vertexAttributes.data();

    VkPipelineInputAssemblyStateCreateInfo inputAssembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    inputAssembly.topology = toVkTopology(desc.topology);

    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;

    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.depthClampEnable = desc.depth.clamp;
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = toVkCullMode(desc.cull);
    // With the negative viewport height, counter-clockwise in y-up NDC stays counter-clockwise here.
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    // Always on: the bias values are dynamic state, zero when a pipeline asks for none.
    raster.depthBiasEnable = VK_TRUE;
    raster.lineWidth = 1.0f;

    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VkSampleCountFlagBits(desc.samples); // the RHI's counts are the flag bits

    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = desc.depth.test;
    depth.depthWriteEnable = desc.depth.write;
    depth.depthCompareOp = toVkCompareOp(context_->conventions.depthCompareOp(desc.depth.compare));

    std::vector<VkPipelineColorBlendAttachmentState> blends;
    for (const rhi::ColorTarget& c : desc.colorTargets)
        blends.push_back(blendAttachment(c));
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = std::uint32_t(blends.size());
    blend.pAttachments = blends.data();

    const std::array<VkDynamicState, 3> dynamicStates{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                                      VK_DYNAMIC_STATE_DEPTH_BIAS};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = std::uint32_t(dynamicStates.size());
    dynamic.pDynamicStates = dynamicStates.data();

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.stageCount = std::uint32_t(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &inputAssembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = desc.depthFormat ? &depth : nullptr;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = descriptors_.layout;
    info.renderPass = renderPass_;
    VkPipeline pipeline = VK_NULL_HANDLE;
    check(vkCreateGraphicsPipelines(context_->device, context_->pipelineCache, 1, &info, nullptr, &pipeline),
          fmt::format("vkCreateGraphicsPipelines ('{}')", desc.debugName));
    pipeline_ = UniquePipeline(context_->device, pipeline);
    context_->setName(VK_OBJECT_TYPE_PIPELINE, pipeline, desc.debugName);
}

VulkanComputePipeline::VulkanComputePipeline(std::shared_ptr<Context> context, const rhi::ComputePipelineDesc& desc)
    : ComputePipeline(desc.compute->compiled()), context_(std::move(context)), desc_(desc)
{
    const auto* shader = dynamic_cast<const VulkanShader*>(desc.compute);
    if (!shader)
        throw rhi::Error(fmt::format("compute pipeline '{}': shader '{}' was not created by a Vulkan device",
                                     desc.debugName, desc.compute->compiled().name));
    descriptors_ = describeDescriptors(*context_, desc.debugName, bindings(), desc.bindingSetLayouts,
                                       VK_SHADER_STAGE_COMPUTE_BIT, VK_PIPELINE_BIND_POINT_COMPUTE);
    const StageModule compute(*context_, *shader, descriptors_);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                  nullptr,
                  0,
                  VK_SHADER_STAGE_COMPUTE_BIT,
                  compute.module(),
                  "main",
                  nullptr};
    info.layout = descriptors_.layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    check(vkCreateComputePipelines(context_->device, context_->pipelineCache, 1, &info, nullptr, &pipeline),
          fmt::format("vkCreateComputePipelines ('{}')", desc.debugName));
    pipeline_ = UniquePipeline(context_->device, pipeline);
    context_->setName(VK_OBJECT_TYPE_PIPELINE, pipeline, desc.debugName);
}

} // namespace penumbra::vulkan
