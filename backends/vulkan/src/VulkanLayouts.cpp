#include "VulkanLayouts.hpp"

#include "VulkanCheck.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::vulkan {

VkDescriptorType drawDescriptorType(rhi::BindingKind kind)
{
    return kind == rhi::BindingKind::UniformBuffer ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC
                                                   : setDescriptorType(kind);
}

VkDescriptorType setDescriptorType(rhi::BindingKind kind)
{
    switch (kind) {
    case rhi::BindingKind::UniformBuffer:
        return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case rhi::BindingKind::SampledTexture:
        return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    case rhi::BindingKind::StorageBuffer:
        return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    case rhi::BindingKind::StorageTexture:
        break;
    }
    return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
}

VkDescriptorSetLayout LayoutCache::setLayout(const std::vector<LayoutBinding>& bindings, VkShaderStageFlags stages)
{
    std::vector<std::uint32_t> key{stages};
    for (const LayoutBinding& b : bindings)
        key.insert(key.end(), {b.binding, std::uint32_t(b.type)});
    std::lock_guard lock(mutex_);
    auto found = setLayouts_.find(key);
    if (found != setLayouts_.end())
        return found->second.get();
    std::vector<VkDescriptorSetLayoutBinding> vkBindings;
    for (const LayoutBinding& b : bindings)
        vkBindings.push_back({b.binding, b.type, 1, stages, nullptr});
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = std::uint32_t(vkBindings.size());
    info.pBindings = vkBindings.data();
    return setLayouts_
        .emplace(std::move(key), createOwned<UniqueDescriptorSetLayout>(device_, vkCreateDescriptorSetLayout, info,
                                                                        "vkCreateDescriptorSetLayout"))
        .first->second.get();
}

VkDescriptorSetLayout LayoutCache::setLayout(const rhi::BindingSetLayoutDesc& desc)
{
    std::vector<LayoutBinding> bindings;
    for (const rhi::BindingLayoutItem& item : desc.items)
        bindings.push_back({item.binding, setDescriptorType(item.kind)});
    return setLayout(bindings, kBindingSetStages);
}

VkPipelineLayout LayoutCache::pipelineLayout(const std::vector<VkDescriptorSetLayout>& sets)
{
    std::lock_guard lock(mutex_);
    auto found = pipelineLayouts_.find(sets);
    if (found != pipelineLayouts_.end())
        return found->second.get();
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = std::uint32_t(sets.size());
    info.pSetLayouts = sets.data();
    return pipelineLayouts_
        .emplace(sets,
                 createOwned<UniquePipelineLayout>(device_, vkCreatePipelineLayout, info, "vkCreatePipelineLayout"))
        .first->second.get();
}

DescriptorLayout describeDescriptors(Context& context, const std::string& pipeline,
                                     const std::vector<rhi::ShaderBinding>& bindings,
                                     const std::vector<const rhi::BindingSetLayout*>& layouts,
                                     VkShaderStageFlags stages, VkPipelineBindPoint bindPoint)
{
    const VkPhysicalDeviceLimits& limits = context.properties.limits;
    if (layouts.size() + 1 > limits.maxBoundDescriptorSets)
        throw rhi::UnsupportedError(fmt::format("pipeline '{}': {} binding set layouts and the per-draw set, but the "
                                                "device binds at most {} descriptor sets",
                                                pipeline, layouts.size(), limits.maxBoundDescriptorSets));
    DescriptorLayout result;
    result.bindPoint = bindPoint;
    for (const rhi::BindingSetLayout* layout : layouts)
        result.sets.push_back({context.layouts().setLayout(layout->desc()), {}, layout->desc().items});
    std::vector<LayoutBinding> drawLayout;
    for (const rhi::ShaderBinding& b : bindings) {
        std::uint32_t set = result.drawSet();
        for (std::uint32_t i = 0; i < layouts.size(); ++i)
            if (layouts[i]->find(b.binding))
                set = i;
        if (b.binding >= result.placement.size())
            result.placement.resize(b.binding + 1, DescriptorLayout::kUndeclared);
        result.placement[b.binding] = set;
        if (set < result.drawSet()) {
            result.sets[set].bindings.push_back(b);
            continue;
        }
        result.drawBindings.push_back(b);
        drawLayout.push_back({b.binding, drawDescriptorType(b.kind)});
        if (b.kind == rhi::BindingKind::UniformBuffer)
            result.uniformBindings.push_back(b.binding);
    }
    if (result.uniformBindings.size() > limits.maxDescriptorSetUniformBuffersDynamic)
        throw rhi::UnsupportedError(fmt::format("pipeline '{}': {} uniform blocks, but the device binds at most {}",
                                                pipeline, result.uniformBindings.size(),
                                                limits.maxDescriptorSetUniformBuffersDynamic));
    result.drawLayout = context.layouts().setLayout(drawLayout, stages);
    for (const SetSlot& set : result.sets)
        result.setLayouts.push_back(set.layout);
    result.setLayouts.push_back(result.drawLayout);
    result.layout = context.layouts().pipelineLayout(result.setLayouts);
    return result;
}

} // namespace penumbra::vulkan
