// The rules of what a binding number may hold, shared by the single bind calls and binding sets (checked once, when a
// set is created), and the rules of binding set layouts and sets themselves.

#include "Rules.hpp"

#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace penumbra::rhi {

std::string_view bindingKindName(BindingKind kind)
{
    switch (kind) {
    case BindingKind::UniformBuffer:
        return "uniform buffer";
    case BindingKind::SampledTexture:
        return "texture and sampler";
    case BindingKind::StorageBuffer:
        return "storage buffer";
    case BindingKind::StorageTexture:
        break;
    }
    return "storage texture";
}

namespace {

// What a uniform or storage range must keep: its buffer's usage, a size limit and an offset alignment (Capabilities).
struct RangeRule {
    std::string_view kind; // "uniform", "storage"
    BufferUsage usage;
    std::string_view usageName;
    std::uint64_t maxRange;
    std::string_view maxRangeName;
    std::uint64_t alignment;
    std::string_view alignmentName;
};

void checkRange(std::string_view what, const RangeRule& rule, std::uint32_t binding, const BufferDesc& buffer,
                std::uint64_t offset, std::uint64_t size)
{
    checkBufferUsage(what, buffer, rule.usage, rule.usageName);
    if (size == 0)
        throw Error(fmt::format("{}: binding {}: a {} range needs at least 1 byte", what, binding, rule.kind));
    if (size > rule.maxRange)
        throw Error(fmt::format("{}: binding {}: {} bytes exceed Capabilities::{} ({})", what, binding, size,
                                rule.maxRangeName, rule.maxRange));
    checkBufferRange(what, buffer, offset, size);
    if (offset % rule.alignment != 0)
        throw Error(fmt::format("{}: offset {} is not a multiple of Capabilities::{} ({})", what, offset,
                                rule.alignmentName, rule.alignment));
}

} // namespace

void checkUniformRange(std::string_view what, const Capabilities& caps, std::uint32_t binding, const BufferDesc& buffer,
                       std::uint64_t offset, std::uint64_t size)
{
    checkRange(what,
               {"uniform", BufferUsage::Uniform, "Uniform", caps.maxUniformBufferRange, "maxUniformBufferRange",
                caps.uniformBufferOffsetAlignment, "uniformBufferOffsetAlignment"},
               binding, buffer, offset, size);
}

void checkStorageRange(std::string_view what, const Capabilities& caps, std::uint32_t binding, const BufferDesc& buffer,
                       std::uint64_t offset, std::uint64_t size)
{
    checkRange(what,
               {"storage", BufferUsage::Storage, "Storage", caps.maxStorageBufferRange, "maxStorageBufferRange",
                caps.storageBufferOffsetAlignment, "storageBufferOffsetAlignment"},
               binding, buffer, offset, size);
}

void checkStorageTextureBinding(std::string_view what, const Texture& texture, std::uint32_t level)
{
    if (!hasFlag(texture.desc().usage, TextureUsage::Storage))
        throw Error(fmt::format("{}: texture '{}' lacks TextureUsage::Storage", what, texture.desc().debugName));
    checkSubresource(what, texture.desc(), 0, level);
}

void checkBindingSetLayout(const BindingSetLayoutDesc& desc)
{
    std::vector<std::uint32_t> numbers;
    for (const BindingLayoutItem& item : desc.items) {
        if (std::find(numbers.begin(), numbers.end(), item.binding) != numbers.end())
            throw Error(
                fmt::format("binding set layout '{}': binding {} is listed twice", desc.debugName, item.binding));
        numbers.push_back(item.binding);
    }
}

void checkPipelineBindingSetLayouts(const std::string& pipeline, const std::vector<const BindingSetLayout*>& layouts,
                                    const std::vector<ShaderBinding>& bindings)
{
    for (std::size_t i = 0; i < layouts.size(); ++i) {
        if (!layouts[i])
            throw Error(fmt::format("pipeline '{}': bindingSetLayouts[{}] is null", pipeline, i));
        for (std::size_t j = 0; j < i; ++j)
            for (const BindingLayoutItem& item : layouts[i]->desc().items)
                if (layouts[j]->find(item.binding))
                    throw Error(fmt::format("pipeline '{}': binding {} is in binding set layouts '{}' and '{}'",
                                            pipeline, item.binding, layouts[j]->desc().debugName,
                                            layouts[i]->desc().debugName));
    }
    for (const ShaderBinding& b : bindings)
        for (const BindingSetLayout* layout : layouts)
            if (const BindingLayoutItem* item = layout->find(b.binding); item && item->kind != b.kind)
                throw Error(fmt::format("pipeline '{}': binding {} ('{}') is a {} in the shaders, but binding set "
                                        "layout '{}' holds a {} there",
                                        pipeline, b.binding, b.name, bindingKindName(b.kind), layout->desc().debugName,
                                        bindingKindName(item->kind)));
}

void checkBindingSet(const Capabilities& caps, const BindingSetDesc& desc)
{
    const std::string what = fmt::format("binding set '{}'", desc.debugName);
    if (!desc.layout)
        throw Error(fmt::format("{}: BindingSetDesc::layout is null", what));
    const BindingSetLayoutDesc& layout = desc.layout->desc();
    std::vector<std::uint32_t> given;
    for (const BindingSetItem& item : desc.items) {
        const BindingLayoutItem* declared = desc.layout->find(item.binding);
        if (!declared)
            throw Error(fmt::format("{}: binding {} is not in layout '{}'", what, item.binding, layout.debugName));
        if (std::find(given.begin(), given.end(), item.binding) != given.end())
            throw Error(fmt::format("{}: binding {} is given twice", what, item.binding));
        given.push_back(item.binding);
        if (item.kind != declared->kind)
            throw Error(fmt::format("{}: binding {} holds a {}, but layout '{}' declares a {} there", what,
                                    item.binding, bindingKindName(item.kind), layout.debugName,
                                    bindingKindName(declared->kind)));
        const bool buffer = item.kind == BindingKind::UniformBuffer || item.kind == BindingKind::StorageBuffer;
        if (buffer ? !item.buffer : !item.texture || (item.kind == BindingKind::SampledTexture && !item.sampler))
            throw Error(fmt::format("{}: binding {} ({}) names no {}", what, item.binding, bindingKindName(item.kind),
                                    buffer ? "buffer" : (item.texture ? "sampler" : "texture")));
        const std::string itemWhat = fmt::format("{} binding {}", what, item.binding);
        switch (item.kind) {
        case BindingKind::UniformBuffer:
            checkUniformRange(itemWhat, caps, item.binding, item.buffer->desc(), item.offset, item.size);
            break;
        case BindingKind::StorageBuffer:
            checkStorageRange(itemWhat, caps, item.binding, item.buffer->desc(), item.offset, item.size);
            break;
        case BindingKind::SampledTexture:
            checkTextureBinding(itemWhat, caps, *item.texture, *item.sampler);
            break;
        case BindingKind::StorageTexture:
            checkStorageTextureBinding(itemWhat, *item.texture, item.level);
            break;
        }
    }
    for (const BindingLayoutItem& item : layout.items)
        if (std::find(given.begin(), given.end(), item.binding) == given.end())
            throw Error(fmt::format("{}: layout '{}' binding {} ({}) has no item", what, layout.debugName, item.binding,
                                    bindingKindName(item.kind)));
}

} // namespace penumbra::rhi
