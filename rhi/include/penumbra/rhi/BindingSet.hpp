#pragma once

// Binding sets: buffers, textures with their samplers and storage resources gathered once against a layout and bound
// with one CommandList::bindBindingSet call, instead of a bind call per binding after every pipeline change (NVRHI's
// BindingLayout and BindingSet are the model; Vulkan 1.3 section 14.2, "Descriptor Sets").
//
//     auto layout = device.createBindingSetLayout({.items = {{0, rhi::BindingKind::UniformBuffer},
//                                                            {1, rhi::BindingKind::SampledTexture}},
//                                                  .debugName = "shadow maps"});
//     auto set = device.createBindingSet({.layout = layout.get(),
//                                         .items = {rhi::BindingSetItem::uniformBuffer(0, blocks, 0, 256),
//                                                   rhi::BindingSetItem::sampledTexture(1, atlas, sampler)},
//                                         .debugName = "frame 12 shadow maps"});
//     commands.bindPipeline(pipeline); // created with .bindingSetLayouts = {layout.get()}
//     commands.bindBindingSet(*set);

#include "penumbra/rhi/LiveObjects.hpp"
#include "penumbra/rhi/Shader.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace penumbra::rhi {

class Buffer;
class Sampler;
class Texture;

// One binding number of a layout and the kind of resource it holds.
struct BindingLayoutItem {
    std::uint32_t binding = 0;
    BindingKind kind = BindingKind::UniformBuffer;
};

// The binding numbers a set fills, each listed once.
struct BindingSetLayoutDesc {
    std::vector<BindingLayoutItem> items;
    std::string debugName;
};

// What binding sets of one shape hold (Device::createBindingSetLayout).
class BindingSetLayout : private LiveObject<ObjectKind::BindingSet> {
public:
    // The description, items sorted by binding number.
    const BindingSetLayoutDesc& desc() const { return desc_; }
    // The item at `binding`, or null where the layout has none.
    const BindingLayoutItem* find(std::uint32_t binding) const;

private:
    friend class ValidatingDevice;
    explicit BindingSetLayout(BindingSetLayoutDesc desc);

    BindingSetLayoutDesc desc_;
};

// One resource of a set, at a binding number of its layout; the factories fill the fields its kind reads.
struct BindingSetItem {
    std::uint32_t binding = 0;
    BindingKind kind = BindingKind::UniformBuffer;
    const Buffer* buffer = nullptr; // UniformBuffer, StorageBuffer
    std::uint64_t offset = 0; // of a buffer range, aligned as bindUniformBuffer and bindStorageBuffer require
    std::uint64_t size = 0;
    const Texture* texture = nullptr; // SampledTexture, StorageTexture
    const Sampler* sampler = nullptr; // SampledTexture
    std::uint32_t level = 0; // StorageTexture's mip level

    // What bindUniformBuffer(binding, buffer, offset, size) binds.
    static BindingSetItem uniformBuffer(std::uint32_t binding, const Buffer& buffer, std::uint64_t offset,
                                        std::uint64_t size);
    // What bindTexture(binding, texture, sampler) binds.
    static BindingSetItem sampledTexture(std::uint32_t binding, const Texture& texture, const Sampler& sampler);
    // What bindStorageBuffer(binding, buffer, offset, size) binds.
    static BindingSetItem storageBuffer(std::uint32_t binding, const Buffer& buffer, std::uint64_t offset,
                                        std::uint64_t size);
    // What bindStorageTexture(binding, texture, level) binds.
    static BindingSetItem storageTexture(std::uint32_t binding, const Texture& texture, std::uint32_t level = 0);
};

// One item for every binding of `layout`, of the layout's kind. The resources must outlive the set's last submission.
struct BindingSetDesc {
    const BindingSetLayout* layout = nullptr;
    std::vector<BindingSetItem> items;
    std::string debugName;
};

// Resources checked once, when created (usage, ranges, alignment, filtering), and bound together by
// CommandList::bindBindingSet. The set keeps a copy of its layout, which may be destroyed first; the set itself must
// outlive the submission of every list that bound it, as its resources must.
class BindingSet : private LiveObject<ObjectKind::BindingSet> {
public:
    virtual ~BindingSet() = default;
    // The items, sorted by binding number.
    const std::vector<BindingSetItem>& items() const { return items_; }
    // The layout the set was created against.
    const BindingSetLayoutDesc& layout() const { return layout_; }
    const std::string& debugName() const { return debugName_; }

protected:
    // For ValidatingDevice and the backends' sets (ValidatingDevice::apiCreateBindingSet).
    explicit BindingSet(const BindingSetDesc& desc);

private:
    friend class ValidatingDevice;

    std::vector<BindingSetItem> items_;
    BindingSetLayoutDesc layout_;
    std::string debugName_;
};

} // namespace penumbra::rhi
