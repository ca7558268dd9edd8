#pragma once

#include "VulkanContext.hpp"
#include "VulkanDescriptors.hpp"

#include "penumbra/rhi/BindingSet.hpp"

#include <vector>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

// A binding set as a descriptor set of its own, written once when created: the RHI's resources cannot change after
// creation (a recreated resource is a new object, so a new set), and nothing else writes it. A pipeline that lists
// its layout (PipelineDesc::bindingSetLayouts) has it bound with one vkCmdBindDescriptorSets.
class VulkanBindingSet final : public rhi::BindingSet {
public:
    VulkanBindingSet(std::shared_ptr<Context> context, const rhi::BindingSetDesc& desc);

    VkDescriptorSet handle() const { return set_; }
    VkDescriptorSetLayout setLayout() const { return layout_; }
    // Each item's descriptor, in items() order.
    const std::vector<Descriptor>& descriptors() const { return descriptors_; }

private:
    std::shared_ptr<Context> context_;
    VkDescriptorSetLayout layout_ = VK_NULL_HANDLE; // the context's LayoutCache owns it
    UniqueDescriptorPool pool_; // this set's alone: destroying the pool frees the set
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    std::vector<Descriptor> descriptors_;
};

} // namespace penumbra::vulkan
