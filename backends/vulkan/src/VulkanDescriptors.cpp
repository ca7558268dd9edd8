#include "VulkanDescriptors.hpp"

#include "VulkanBindingSet.hpp"
#include "VulkanCheck.hpp"
#include "VulkanResources.hpp"

#include <algorithm>
#include <array>
#include <string>

namespace penumbra::vulkan {
namespace {

constexpr std::uint32_t setsPerPool = 1024;

} // namespace

Descriptor describe(const rhi::BindingSetItem& item, std::string_view what)
{
    const std::string buffer = std::string(what) + ": the buffer";
    const std::string texture = std::string(what) + ": the texture";
    switch (item.kind) {
    case rhi::BindingKind::UniformBuffer:
    case rhi::BindingKind::StorageBuffer:
        return {.kind = item.kind,
                .buffer = vulkanObject<const VulkanBuffer>(*item.buffer, buffer).handle(),
                .offset = item.offset,
                .size = item.size};
    case rhi::BindingKind::SampledTexture: {
        const auto& vk = vulkanObject<const VulkanTexture>(*item.texture, texture);
        return {.kind = item.kind,
                .view = vk.sampledView(),
                .sampler =
                    vulkanObject<const VulkanSampler>(*item.sampler, std::string(what) + ": the sampler").handle(),
                .layout = vk.restingLayout()};
    }
    case rhi::BindingKind::StorageTexture:
        break;
    }
    return {.kind = item.kind,
            .view = vulkanObject<const VulkanTexture>(*item.texture, texture).storageView(item.level),
            .layout = VK_IMAGE_LAYOUT_GENERAL};
}

void DescriptorWrites::add(std::uint32_t binding, const Descriptor& descriptor, bool dynamicUniforms)
{
    entries_.push_back({binding, descriptor,
                        dynamicUniforms ? drawDescriptorType(descriptor.kind) : setDescriptorType(descriptor.kind)});
}

void DescriptorWrites::write(VkDevice device, VkDescriptorSet set)
{
    bufferInfos_.clear();
    imageInfos_.clear();
    writes_.clear();
    // Reserved up front: the writes point into these vectors.
    bufferInfos_.reserve(entries_.size());
    imageInfos_.reserve(entries_.size());
    for (const Entry& e : entries_) {
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.dstSet = set;
        write.dstBinding = e.binding;
        write.descriptorCount = 1;
        write.descriptorType = e.type;
        const Descriptor& d = e.descriptor;
        if (d.kind == rhi::BindingKind::UniformBuffer || d.kind == rhi::BindingKind::StorageBuffer) {
            // A dynamic uniform block's offset is given when the set is bound.
            const bool dynamic = e.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
            bufferInfos_.push_back({d.buffer, dynamic ? 0 : d.offset, d.size});
            write.pBufferInfo = &bufferInfos_.back();
        } else {
            imageInfos_.push_back({d.sampler, d.view, d.layout});
            write.pImageInfo = &imageInfos_.back();
        }
        writes_.push_back(write);
    }
    vkUpdateDescriptorSets(device, std::uint32_t(writes_.size()), writes_.data(), 0, nullptr);
    entries_.clear();
}

UniqueDescriptorPool DescriptorAllocator::createPool() const
{
    const std::array<VkDescriptorPoolSize, 5> sizes{{
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, setsPerPool * 4},
        {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, setsPerPool},
        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, setsPerPool * 4},
        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, setsPerPool},
        {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, setsPerPool},
    }};
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.maxSets = setsPerPool;
    info.poolSizeCount = std::uint32_t(sizes.size());
    info.pPoolSizes = sizes.data();
    return createOwned<UniqueDescriptorPool>(context_->device, vkCreateDescriptorPool, info, "vkCreateDescriptorPool");
}

VkDescriptorSet DescriptorAllocator::allocate(VkDescriptorSetLayout layout)
{
    VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    for (;; ++current_) {
        if (current_ == pools_.size())
            pools_.push_back(createPool());
        info.descriptorPool = pools_[current_].get();
        VkDescriptorSet set = VK_NULL_HANDLE;
        const VkResult result = vkAllocateDescriptorSets(context_->device, &info, &set);
        if (result == VK_SUCCESS)
            return set;
        // A full pool: move on to the next one, creating it if needed.
        if (result != VK_ERROR_OUT_OF_POOL_MEMORY && result != VK_ERROR_FRAGMENTED_POOL)
            check(result, "vkAllocateDescriptorSets");
    }
}

void DescriptorAllocator::reset()
{
    for (std::size_t i = 0; i < pools_.size() && i <= current_; ++i)
        check(vkResetDescriptorPool(context_->device, pools_[i].get(), 0), "vkResetDescriptorPool");
    current_ = 0;
}

DescriptorBinder::Slot& DescriptorBinder::slot(std::uint32_t binding)
{
    if (binding >= slots_.size())
        slots_.resize(binding + 1);
    return slots_[binding];
}

void DescriptorBinder::setPipeline(const DescriptorLayout& pipeline)
{
    pipeline_ = &pipeline;
    // Pipelines of one layout may declare different bindings of a binding set layout.
    if (!pipeline.sets.empty())
        dirty_ = setsDirty_ = true;
    if (pipeline.layout == layout_)
        return;
    layout_ = pipeline.layout;
    // Sets stay bound up to the first index whose layout differs (pipeline layout compatibility, section 14.2.2).
    std::size_t same = 0;
    while (same < boundLayouts_.size() && same < pipeline.setLayouts.size() &&
           boundLayouts_[same] == pipeline.setLayouts[same])
        ++same;
    boundLayouts_ = pipeline.setLayouts;
    bound_.resize(boundLayouts_.size());
    for (std::size_t i = same; i < bound_.size(); ++i)
        bound_[i].valid = false;
    if (pipeline.drawLayout != drawLayout_) {
        drawLayout_ = pipeline.drawLayout;
        drawDirty_ = true;
    }
    dirty_ = true;
}

void DescriptorBinder::setBindingSet(const VulkanBindingSet& set)
{
    const std::vector<rhi::BindingSetItem>& items = set.items();
    for (std::size_t i = 0; i < items.size(); ++i)
        place(items[i].binding, set.descriptors()[i], &set);
}

void DescriptorBinder::place(std::uint32_t binding, const Descriptor& descriptor, const VulkanBindingSet* from)
{
    Slot& s = slot(binding);
    const bool sameResource = s.filled && s.descriptor.sameResource(descriptor);
    const bool sameOffset = s.descriptor.offset == descriptor.offset;
    if (sameResource && sameOffset && s.from == from)
        return;
    s = {descriptor, true, from};
    // Nothing to mark without a pipeline, or for a binding it does not read: the next setPipeline marks what its sets
    // need.
    const std::uint32_t set = pipeline_ ? pipeline_->setOf(binding) : DescriptorLayout::kUndeclared;
    if (set == DescriptorLayout::kUndeclared)
        return;
    if (set < pipeline_->drawSet()) {
        setsDirty_ = true;
    } else if (!sameResource || (!sameOffset && descriptor.kind != rhi::BindingKind::UniformBuffer)) {
        drawDirty_ = true;
    } else if (!sameOffset) {
        offsetsDirty_ = true;
    } else {
        return; // the same descriptor, now from another source
    }
    dirty_ = true;
}

void DescriptorBinder::rebind()
{
    for (BoundSet& b : bound_)
        b.valid = false;
    dirty_ = pipeline_ != nullptr;
}

void DescriptorBinder::reset()
{
    allocator_.reset();
    slots_.clear();
    pipeline_ = nullptr;
    layout_ = VK_NULL_HANDLE;
    drawLayout_ = VK_NULL_HANDLE;
    boundLayouts_.clear();
    bound_.clear();
    chosen_.clear();
    drawSet_ = VK_NULL_HANDLE;
    dirty_ = setsDirty_ = drawDirty_ = offsetsDirty_ = false;
}

DescriptorBinder::Choice DescriptorBinder::choose(const SetSlot& set)
{
    if (set.bindings.empty())
        return {};
    const VulkanBindingSet* from = slot(set.bindings.front().binding).from;
    bool whole = from && from->setLayout() == set.layout;
    for (const rhi::ShaderBinding& b : set.bindings)
        whole = whole && slot(b.binding).from == from;
    if (whole)
        return {from->handle(), true};
    // Single binds, or a set of another layout, hold some of its bindings: a set written from what is bound, as the
    // per-draw one is. The validation layer has checked that every binding the shaders declare holds something; the
    // layout's other bindings get placeholders, since lavapipe reads every descriptor of a bound set
    // (VulkanDevice::makePlaceholders).
    const VkDescriptorSet written = allocator_.allocate(set.layout);
    for (const rhi::BindingLayoutItem& item : set.items) {
        const bool declared = std::any_of(set.bindings.begin(), set.bindings.end(),
                                          [&](const rhi::ShaderBinding& b) { return b.binding == item.binding; });
        writes_.add(item.binding, declared ? slot(item.binding).descriptor : placeholder(item.kind), false);
    }
    writes_.write(allocator_.device(), written);
    ++counts_.setsWritten;
    return {written, false};
}

Descriptor DescriptorBinder::placeholder(rhi::BindingKind kind) const
{
    const Context::Placeholders& p = allocator_.context().placeholders;
    switch (kind) {
    case rhi::BindingKind::UniformBuffer:
    case rhi::BindingKind::StorageBuffer:
        return {.kind = kind, .buffer = p.buffer, .size = 16};
    case rhi::BindingKind::SampledTexture:
        return {.kind = kind, .view = p.sampledView, .sampler = p.sampler, .layout = p.sampledLayout};
    case rhi::BindingKind::StorageTexture:
        break;
    }
    return {.kind = kind, .view = p.storageView, .layout = VK_IMAGE_LAYOUT_GENERAL};
}

void DescriptorBinder::writeDrawSet()
{
    drawSet_ = allocator_.allocate(drawLayout_);
    for (const rhi::ShaderBinding& b : pipeline_->drawBindings)
        writes_.add(b.binding, slot(b.binding).descriptor, true);
    writes_.write(allocator_.device(), drawSet_);
    ++counts_.setsWritten;
}

void DescriptorBinder::bindSet(VkCommandBuffer commandBuffer, std::uint32_t index, const Choice& set, bool force)
{
    BoundSet& b = bound_[index];
    if (!force && b.valid && b.set == set.set)
        return;
    vkCmdBindDescriptorSets(commandBuffer, pipeline_->bindPoint, layout_, index, 1, &set.set,
                            std::uint32_t(offsets_.size()), offsets_.data());
    ++counts_.bindCalls;
    if (set.bindingSet)
        ++counts_.bindingSetBinds;
    // Binding over an incompatible set disturbs the sets above it (section 14.2.2); the caller binds those next.
    if (!b.valid)
        for (std::size_t i = index + 1; i < bound_.size(); ++i)
            bound_[i].valid = false;
    b = {set.set, true};
}

void DescriptorBinder::bind(VkCommandBuffer commandBuffer)
{
    const DescriptorLayout& pipeline = *pipeline_;
    if (setsDirty_) {
        chosen_.resize(pipeline.sets.size());
        for (std::size_t i = 0; i < pipeline.sets.size(); ++i)
            chosen_[i] = choose(pipeline.sets[i]);
    }
    offsets_.clear();
    for (std::uint32_t i = 0; i < pipeline.sets.size(); ++i)
        if (chosen_[i].set != VK_NULL_HANDLE)
            bindSet(commandBuffer, i, chosen_[i], false);
    if (!pipeline.drawBindings.empty()) {
        if (drawDirty_)
            writeDrawSet();
        for (std::uint32_t binding : pipeline.uniformBindings)
            offsets_.push_back(std::uint32_t(slot(binding).descriptor.offset));
        bindSet(commandBuffer, pipeline.drawSet(), {drawSet_, false}, drawDirty_ || offsetsDirty_);
    }
    dirty_ = setsDirty_ = drawDirty_ = offsetsDirty_ = false;
}

} // namespace penumbra::vulkan
