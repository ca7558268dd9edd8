#pragma once

#include "VulkanContext.hpp"
#include "VulkanLayouts.hpp"

#include "penumbra/rhi/BindingSet.hpp"
#include "penumbra/vulkan/Native.hpp"

#include <string_view>
#include <vector>
#include <vulkan/vulkan.h>

namespace penumbra::vulkan {

class VulkanBindingSet;

// What one binding number holds, in Vulkan handles.
struct Descriptor {
    rhi::BindingKind kind = rhi::BindingKind::UniformBuffer;
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize offset = 0; // of a buffer range: a dynamic offset in the per-draw set, written in a binding set
    VkDeviceSize size = 0;
    VkImageView view = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;

    // The same resource, whatever the offset.
    bool sameResource(const Descriptor& other) const
    {
        return kind == other.kind && buffer == other.buffer && size == other.size && view == other.view &&
               sampler == other.sampler && layout == other.layout;
    }
};

// The descriptor of what a set item (or the single bind call it stands for, `what`) binds.
Descriptor describe(const rhi::BindingSetItem& item, std::string_view what);

// Writes descriptors into a set with one vkUpdateDescriptorSets.
class DescriptorWrites {
public:
    // `dynamicUniforms`: uniform blocks of the per-draw set, whose offsets come with the bind.
    void add(std::uint32_t binding, const Descriptor& descriptor, bool dynamicUniforms);
    void write(VkDevice device, VkDescriptorSet set);

private:
    struct Entry {
        std::uint32_t binding;
        Descriptor descriptor;
        VkDescriptorType type;
    };
    std::vector<Entry> entries_;
    std::vector<VkDescriptorBufferInfo> bufferInfos_;
    std::vector<VkDescriptorImageInfo> imageInfos_;
    std::vector<VkWriteDescriptorSet> writes_;
};

// Descriptor sets for one command list: allocated from a growing list of pools, all reset after submit.
class DescriptorAllocator {
public:
    explicit DescriptorAllocator(std::shared_ptr<Context> context) : context_(std::move(context)) {}

    VkDescriptorSet allocate(VkDescriptorSetLayout layout);
    void reset();
    VkDevice device() const { return context_->device; }
    const Context& context() const { return *context_; }

private:
    UniqueDescriptorPool createPool() const;

    std::shared_ptr<Context> context_;
    std::vector<UniqueDescriptorPool> pools_;
    std::size_t current_ = 0;
};

// What a command list has bound to each binding number and the descriptor sets that hold it, for one bind point
// (graphics or compute; a list keeps one binder per bind point, both given every binding).
// The sets of the pipeline's binding set layouts (DescriptorLayout::sets) are the bound binding sets' own, each bound
// with one call, unless single binds replaced part of one: then a set is written from what is bound. The per-draw set
// is written only when its buffers, textures or samplers change; changed uniform offsets alone are new dynamic offsets.
class DescriptorBinder {
public:
    explicit DescriptorBinder(std::shared_ptr<Context> context) : allocator_(std::move(context)) {}

    void setPipeline(const DescriptorLayout& pipeline);
    // A single bind call's resource.
    void set(std::uint32_t binding, const Descriptor& descriptor) { place(binding, descriptor, nullptr); }
    // Every item of a binding set.
    void setBindingSet(const VulkanBindingSet& set);
    // Before a draw or dispatch: binds what changed, writing the sets that need it.
    void flush(VkCommandBuffer commandBuffer)
    {
        if (dirty_)
            bind(commandBuffer);
    }
    // Another pipeline layout took the bind point: the next flush binds every set again.
    void rebind();
    // After submit: the sets are gone and bound resources may be destroyed.
    void reset();
    // Since the binder was created (reset keeps them).
    const DescriptorCounts& counts() const { return counts_; }

private:
    struct Slot {
        Descriptor descriptor;
        bool filled = false;
        const VulkanBindingSet* from = nullptr; // the binding set that bound it, until a single bind replaces it
    };
    struct BoundSet {
        VkDescriptorSet set = VK_NULL_HANDLE;
        bool valid = false; // bound with a pipeline layout compatible with the current one for its index
    };
    struct Choice {
        VkDescriptorSet set = VK_NULL_HANDLE; // null: the pipeline's shaders use no binding of it
        bool bindingSet = false; // a binding set's own
    };

    void place(std::uint32_t binding, const Descriptor& descriptor, const VulkanBindingSet* from);
    Slot& slot(std::uint32_t binding);
    void bind(VkCommandBuffer commandBuffer);
    Choice choose(const SetSlot& set);
    // What a written binding set layout's set holds where the pipeline's shaders declare nothing.
    Descriptor placeholder(rhi::BindingKind kind) const;
    void writeDrawSet();
    // Binds `set` at `index` unless it is bound there already and `force` is false.
    void bindSet(VkCommandBuffer commandBuffer, std::uint32_t index, const Choice& set, bool force);

    DescriptorAllocator allocator_;
    std::vector<Slot> slots_; // by binding number
    const DescriptorLayout* pipeline_ = nullptr;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout drawLayout_ = VK_NULL_HANDLE;
    std::vector<VkDescriptorSetLayout> boundLayouts_; // the set layouts of the layout the sets were bound with
    std::vector<BoundSet> bound_; // by set index
    std::vector<Choice> chosen_; // for the pipeline's binding set layouts
    VkDescriptorSet drawSet_ = VK_NULL_HANDLE;
    bool dirty_ = false; // something below is
    bool setsDirty_ = false; // choose the binding set layouts' sets again
    bool drawDirty_ = false; // write a new per-draw set
    bool offsetsDirty_ = false; // bind the per-draw set again with new dynamic offsets
    std::vector<std::uint32_t> offsets_;
    DescriptorWrites writes_;
    DescriptorCounts counts_;
};

} // namespace penumbra::vulkan
