#include "penumbra/rhi/BindingSet.hpp"

#include <algorithm>

namespace penumbra::rhi {
namespace {

template <typename Item>
void sortByBinding(std::vector<Item>& items)
{
    std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.binding < b.binding; });
}

} // namespace

BindingSetLayout::BindingSetLayout(BindingSetLayoutDesc desc) : desc_(std::move(desc)) { sortByBinding(desc_.items); }

const BindingLayoutItem* BindingSetLayout::find(std::uint32_t binding) const
{
    const auto it = std::find_if(desc_.items.begin(), desc_.items.end(),
                                 [binding](const BindingLayoutItem& item) { return item.binding == binding; });
    return it == desc_.items.end() ? nullptr : &*it;
}

BindingSetItem BindingSetItem::uniformBuffer(std::uint32_t binding, const Buffer& buffer, std::uint64_t offset,
                                             std::uint64_t size)
{
    return {.binding = binding, .kind = BindingKind::UniformBuffer, .buffer = &buffer, .offset = offset, .size = size};
}

BindingSetItem BindingSetItem::sampledTexture(std::uint32_t binding, const Texture& texture, const Sampler& sampler)
{
    return {.binding = binding, .kind = BindingKind::SampledTexture, .texture = &texture, .sampler = &sampler};
}

BindingSetItem BindingSetItem::storageBuffer(std::uint32_t binding, const Buffer& buffer, std::uint64_t offset,
                                             std::uint64_t size)
{
    return {.binding = binding, .kind = BindingKind::StorageBuffer, .buffer = &buffer, .offset = offset, .size = size};
}

BindingSetItem BindingSetItem::storageTexture(std::uint32_t binding, const Texture& texture, std::uint32_t level)
{
    return {.binding = binding, .kind = BindingKind::StorageTexture, .texture = &texture, .level = level};
}

BindingSet::BindingSet(const BindingSetDesc& desc)
    : items_(desc.items), layout_(desc.layout->desc()), debugName_(desc.debugName)
{
    sortByBinding(items_);
}

} // namespace penumbra::rhi
