#pragma once

// Descriptor-set and pipeline layouts, one per distinct shape, shared by a device's pipelines and binding sets.
// A pipeline's layout holds a descriptor set per binding set layout it lists (PipelineDesc::bindingSetLayouts), in
// that order, and last the set of its other bindings, which command lists write per draw (DescriptorBinder). The
// binding sets come first so that switching between pipelines that list the same layouts keeps their sets bound:
// a set stays valid for pipeline layouts that define sets 0 to its own identically (Vulkan 1.3 section 14.2.2,
// "Pipeline Layouts", pipeline layout compatibility).

#include "VulkanContext.hpp"

#include "penumbra/rhi/BindingSet.hpp"
#include "penumbra/rhi/Shader.hpp"

#include <limits>
#include <map>
#include <mutex>
#include <string>
#include <vector>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

// The stages of a binding set's descriptors: every stage an RHI pipeline has, so that one descriptor set serves
// graphics and compute pipelines (a bound set's layout must be identically defined to the pipeline's, section 14.2.2).
inline constexpr VkShaderStageFlags kBindingSetStages =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;

// The descriptor type of a binding kind in the per-draw set: a uniform block is dynamic there, so that a new offset
// per draw is a dynamic offset, not a new descriptor set.
VkDescriptorType drawDescriptorType(rhi::BindingKind kind);
// The descriptor type in a binding set's descriptor set: a uniform range is written once, offset included.
VkDescriptorType setDescriptorType(rhi::BindingKind kind);

struct LayoutBinding {
    std::uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
};

class LayoutCache {
public:
    explicit LayoutCache(VkDevice device) : device_(device) {}

    VkDescriptorSetLayout setLayout(const std::vector<LayoutBinding>& bindings, VkShaderStageFlags stages);
    // The descriptor set layout of a binding set layout's sets.
    VkDescriptorSetLayout setLayout(const rhi::BindingSetLayoutDesc& desc);
    VkPipelineLayout pipelineLayout(const std::vector<VkDescriptorSetLayout>& sets);

private:
    VkDevice device_;
    std::mutex mutex_;
    std::map<std::vector<std::uint32_t>, UniqueDescriptorSetLayout> setLayouts_;
    std::map<std::vector<VkDescriptorSetLayout>, UniquePipelineLayout> pipelineLayouts_; // destroyed first
};

// A descriptor set of a pipeline's layout that binding sets of one layout fill.
struct SetSlot {
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    std::vector<rhi::ShaderBinding> bindings; // the ones the shaders declare, sorted by number
    std::vector<rhi::BindingLayoutItem> items; // every binding of the layout
};

// A graphics or compute pipeline's descriptor sets, as DescriptorBinder binds them.
struct DescriptorLayout {
    static constexpr std::uint32_t kUndeclared = std::numeric_limits<std::uint32_t>::max();

    std::vector<SetSlot> sets; // set index i: PipelineDesc::bindingSetLayouts[i]
    std::vector<rhi::ShaderBinding> drawBindings; // the per-draw set's, at index drawSet(), sorted by number
    std::vector<std::uint32_t> uniformBindings; // its uniform blocks, in the order of their dynamic offsets
    VkDescriptorSetLayout drawLayout = VK_NULL_HANDLE;
    std::vector<VkDescriptorSetLayout> setLayouts; // every set's, by index: the pipeline layout's
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipelineBindPoint bindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    std::vector<std::uint32_t> placement; // by binding number: the set index of a declared binding, else kUndeclared

    std::uint32_t drawSet() const { return std::uint32_t(sets.size()); }
    // The set index of a binding the shaders declare, else kUndeclared.
    std::uint32_t setOf(std::uint32_t binding) const
    {
        return binding < placement.size() ? placement[binding] : kUndeclared;
    }
};

// A pipeline's `bindings` (every one its shaders declare, sorted) placed in the sets of `layouts` and the per-draw set.
// Throws rhi::UnsupportedError past the device's limits on sets and dynamic uniform blocks.
DescriptorLayout describeDescriptors(Context& context, const std::string& pipeline,
                                     const std::vector<rhi::ShaderBinding>& bindings,
                                     const std::vector<const rhi::BindingSetLayout*>& layouts,
                                     VkShaderStageFlags stages, VkPipelineBindPoint bindPoint);

} // namespace penumbra::vulkan
