#include "penumbra/rhi/Hazards.hpp"

namespace penumbra::rhi {
namespace {

bool covers(const Use& visible, const Use& use)
{
    return hasAll(visible.stages, use.stages) && hasAll(visible.access, use.access);
}

Use merged(const Use& a, const Use& b) { return {a.stages | b.stages, a.access | b.access}; }

// The writes of a use, in the stages that make them.
Use writesOf(const Use& use)
{
    Use writes{Stage::None, use.access & kWriteAccesses};
    if (hasFlag(writes.access, Access::AttachmentWrite))
        writes.stages |= Stage::Attachments;
    if (hasFlag(writes.access, Access::CopyWrite))
        writes.stages |= Stage::Copy;
    if (hasFlag(writes.access, Access::StorageBufferWrite | Access::StorageImageWrite))
        writes.stages |= use.stages & (Stage::ComputeShader | Stage::VertexShader | Stage::FragmentShader);
    return writes;
}

} // namespace

void Barrier::merge(const Barrier& other)
{
    src = merged(src, other.src);
    dst = merged(dst, other.dst);
}

Use graphicsUses(const BufferDesc& desc)
{
    Use use;
    const auto add = [&](BufferUsage usage, Stage stages, Access access) {
        if (hasFlag(desc.usage, usage))
            use = merged(use, {stages, access});
    };
    add(BufferUsage::Vertex, Stage::VertexInput, Access::VertexRead);
    add(BufferUsage::Index, Stage::VertexInput, Access::IndexRead);
    add(BufferUsage::Uniform, Stage::VertexShader | Stage::FragmentShader, Access::UniformRead);
    add(BufferUsage::Storage, Stage::VertexShader | Stage::FragmentShader, Access::StorageBufferRead);
    add(BufferUsage::Indirect, Stage::DrawIndirect, Access::IndirectRead);
    return use;
}

Use graphicsUses(const TextureDesc& desc)
{
    Use use;
    if (hasFlag(desc.usage, TextureUsage::Sampled))
        use = merged(use, {Stage::VertexShader | Stage::FragmentShader, Access::SampledRead});
    if (hasFlag(desc.usage, TextureUsage::RenderTarget))
        use = merged(use, {Stage::Attachments, Access::AttachmentRead | Access::AttachmentWrite});
    return use;
}

void HazardTracker::use(const void* resource, Use graphics, Use use, Barrier& barrier)
{
    auto [found, fresh] = states_.try_emplace(resource);
    State& s = found->second;
    if (fresh)
        s.graphics = graphics;
    // Passes since the resource was last ordered after graphics may have used it as its usages allow: their writes
    // come before any access, their reads before a write.
    if (s.passes < passes_ && s.graphics.stages != Stage::None) {
        if (use.writes())
            barrier.merge({{s.graphics.stages, s.graphics.access & kWriteAccesses}, use});
        else if (s.graphics.writes())
            barrier.merge({writesOf(s.graphics), use});
    }
    s.passes = passes_;
    if (use.writes()) {
        if (s.write.stages != Stage::None)
            barrier.merge({s.write, use}); // write after write (and the read of a read-modify-write)
        if (s.reads.stages != Stage::None)
            barrier.merge({{s.reads.stages, Access::None}, use}); // write after read: execution only
        s.write = writesOf(use);
        s.visible = {};
        s.reads = {};
        s.readsOrdered = false;
        s.host = s.host || hasFlag(use.access, Access::StorageBufferWrite);
        return;
    }
    if (s.write.stages != Stage::None && !covers(s.visible, use)) {
        barrier.merge({s.write, use});
        s.visible = merged(s.visible, use);
    }
    s.reads = merged(s.reads, use);
    s.readsOrdered = false;
}

Barrier HazardTracker::beginPass()
{
    ++passes_;
    Barrier barrier;
    for (auto& [resource, s] : states_) {
        if (s.write.stages != Stage::None && s.graphics.stages != Stage::None && !covers(s.visible, s.graphics)) {
            barrier.merge({s.write, s.graphics});
            s.visible = merged(s.visible, s.graphics);
        }
        if (s.reads.stages != Stage::None && s.graphics.writes() && !s.readsOrdered) {
            barrier.merge({{s.reads.stages, Access::None}, writesOf(s.graphics)});
            s.readsOrdered = true;
        }
    }
    return barrier;
}

Barrier HazardTracker::copy(const void* resource, Use use)
{
    Barrier barrier;
    const auto found = states_.find(resource);
    if (found == states_.end())
        return barrier;
    State& s = found->second;
    if (s.write.stages != Stage::None && !covers(s.visible, use)) {
        barrier.merge({s.write, use});
        s.visible = merged(s.visible, use);
    }
    if (use.writes() && s.reads.stages != Stage::None)
        barrier.merge({{s.reads.stages, Access::None}, use});
    if (use.writes()) {
        // The copy's write replaces the dispatch's; what follows a copy is the backend's to order (see the header).
        states_.erase(found);
    }
    return barrier;
}

Barrier HazardTracker::finish()
{
    Barrier barrier;
    const Use host{Stage::Host, Access::HostRead};
    for (auto& [resource, s] : states_)
        if (s.host && s.write.stages != Stage::None && !covers(s.visible, host)) {
            barrier.merge({s.write, host});
            s.visible = merged(s.visible, host);
        }
    return barrier;
}

void HazardTracker::reset()
{
    states_.clear();
    passes_ = 0;
}

} // namespace penumbra::rhi
