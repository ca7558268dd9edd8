#include "penumbra/rhi/Hazards.hpp"

#include <array>
#include <utility>

namespace penumbra::rhi {
namespace {

// Each state's name and what it stands for, written once for stateUse and resourceStateName.
struct StateMeaning {
    ResourceState state;
    const char* name;
    Use use;
};
constexpr Stage kShaderStages = Stage::VertexShader | Stage::FragmentShader | Stage::ComputeShader;
constexpr std::array<StateMeaning, 10> kStateMeanings{{
    {ResourceState::VertexBuffer, "VertexBuffer", {Stage::VertexInput, Access::VertexRead}},
    {ResourceState::IndexBuffer, "IndexBuffer", {Stage::VertexInput, Access::IndexRead}},
    {ResourceState::IndirectArgument, "IndirectArgument", {Stage::DrawIndirect, Access::IndirectRead}},
    {ResourceState::UniformBuffer, "UniformBuffer", {kShaderStages, Access::UniformRead}},
    {ResourceState::ShaderRead,
     "ShaderRead",
     {kShaderStages, Access::SampledRead | Access::StorageBufferRead | Access::StorageImageRead}},
    {ResourceState::ShaderWrite,
     "ShaderWrite",
     {Stage::ComputeShader,
      Access::StorageBufferRead | Access::StorageBufferWrite | Access::StorageImageRead | Access::StorageImageWrite}},
    {ResourceState::RenderTarget,
     "RenderTarget",
     {Stage::Attachments, Access::AttachmentRead | Access::AttachmentWrite}},
    {ResourceState::DepthRead, "DepthRead", {Stage::Attachments, Access::AttachmentRead}},
    {ResourceState::CopySource, "CopySource", {Stage::Copy, Access::CopyRead}},
    {ResourceState::CopyDestination, "CopyDestination", {Stage::Copy, Access::CopyWrite}},
}};

// The states a declared state covers: a write state covers the reads it makes.
ResourceState coveredStates(ResourceState state)
{
    if (hasFlag(state, ResourceState::ShaderWrite))
        state |= ResourceState::ShaderRead;
    if (hasFlag(state, ResourceState::RenderTarget))
        state |= ResourceState::DepthRead;
    return state;
}

bool useCovers(const Use& visible, const Use& use)
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

std::string resourceStateName(ResourceState state)
{
    std::string name;
    for (const StateMeaning& m : kStateMeanings)
        if (hasFlag(state, m.state))
            name += (name.empty() ? "" : " | ") + std::string(m.name);
    return name.empty() ? "Undefined" : name;
}

Use stateUse(ResourceState state)
{
    Use use;
    for (const StateMeaning& m : kStateMeanings)
        if (hasFlag(state, m.state))
            use = merged(use, m.use);
    return use;
}

Barrier stateBarrier(ResourceState before, ResourceState after)
{
    Barrier barrier;
    const Use from = stateUse(before);
    const Use to = stateUse(after);
    if (from.writes())
        barrier.merge({writesOf(from), to}); // read or write after write
    else if (to.writes() && from.stages != Stage::None)
        barrier.merge({{from.stages, Access::None}, to}); // write after read: execution only
    return barrier;
}

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
    if (s.write.stages != Stage::None && !useCovers(s.visible, use)) {
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
        if (s.write.stages != Stage::None && s.graphics.stages != Stage::None && !useCovers(s.visible, s.graphics)) {
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
    if (s.write.stages != Stage::None && !useCovers(s.visible, use)) {
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
        if (s.host && s.write.stages != Stage::None && !useCovers(s.visible, host)) {
            barrier.merge({s.write, host});
            s.visible = merged(s.visible, host);
        }
    return barrier;
}

void HazardTracker::reset()
{
    states_.clear();
    passes_ = 0;
    declared_.clear();
    scope_ = {};
}

Barrier HazardTracker::declare(std::span<const ResourceBarrier> barriers, std::string pass, std::size_t labels)
{
    Barrier barrier;
    scope_ = {true, std::move(pass), labels, {}};
    for (const ResourceBarrier& b : barriers) {
        const void* resource = b.texture ? static_cast<const void*>(b.texture) : static_cast<const void*>(b.buffer);
        barrier.merge(stateBarrier(b.before, b.after));
        declared_[resource] = b.after;
        scope_.states[resource] = b.after;
    }
    return barrier;
}

void HazardTracker::labelClosed(std::size_t labels)
{
    if (scope_.open && labels < scope_.labels)
        scope_ = {};
}

ResourceState HazardTracker::declared(const void* resource) const
{
    const auto found = declared_.find(resource);
    return found == declared_.end() ? ResourceState::Undefined : found->second;
}

ResourceState HazardTracker::scoped(const void* resource) const
{
    const auto found = scope_.states.find(resource);
    return found == scope_.states.end() ? ResourceState::Undefined : found->second;
}

bool HazardTracker::covers(const void* resource, ResourceState needed) const
{
    if (!scope_.open || !declared_.contains(resource))
        return true;
    return hasAll(coveredStates(scoped(resource)), needed);
}

} // namespace penumbra::rhi
