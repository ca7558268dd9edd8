#include "VulkanBindingSet.hpp"

#include "VulkanCheck.hpp"
#include "VulkanLayouts.hpp"

#include <fmt/format.h>
#include <map>

namespace penumbra::vulkan {

VulkanBindingSet::VulkanBindingSet(std::shared_ptr<Context> context, const rhi::BindingSetDesc& desc)
    : BindingSet(desc), context_(std::move(context)), layout_(context_->layouts().setLayout(BindingSet::layout()))
{
    const std::string what = fmt::format("binding set '{}'", debugName());
    std::map<VkDescriptorType, std::uint32_t> counts;
    DescriptorWrites writes;
    for (const rhi::BindingSetItem& item : items()) {
        descriptors_.push_back(describe(item, what));
        writes.add(item.binding, descriptors_.back(), false);
        ++counts[setDescriptorType(item.kind)];
    }
    std::vector<VkDescriptorPoolSize> sizes;
    for (const auto& [type, count] : counts)
        sizes.push_back({type, count});
    if (sizes.empty()) // an empty layout's set still comes from a pool, which needs a size
        sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1});
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = std::uint32_t(sizes.size());
    poolInfo.pPoolSizes = sizes.data();
    pool_ =
        createOwned<UniqueDescriptorPool>(context_->device, vkCreateDescriptorPool, poolInfo, "vkCreateDescriptorPool");
    VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    info.descriptorPool = pool_.get();
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout_;
    check(vkAllocateDescriptorSets(context_->device, &info, &set_), "vkAllocateDescriptorSets");
    writes.write(context_->device, set_);
    context_->setName(VK_OBJECT_TYPE_DESCRIPTOR_SET, set_, debugName());
}

} // namespace penumbra::vulkan
