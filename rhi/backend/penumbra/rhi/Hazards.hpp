#pragma once

// For backends: the barriers a command list needs, in API-neutral terms. ValidatingCommandList keeps one
// HazardTracker per list and hands each barrier it derives to the backend's apiBarrier, which turns it into a
// Vulkan pipeline barrier or a GL glMemoryBarrier.
//
// What is ordered where: render passes order themselves against earlier and later passes and copies (Vulkan
// subpass dependencies over the graphics and transfer stages), and a copy orders everything after it (a full
// barrier). Compute is in neither, so every hazard with a dispatch on one side is the tracker's: a dispatch after a
// pass or a copy, a pass, copy or host read after a dispatch, and one dispatch after another.
//
// Uses are declared per resource (use()); the list declares what each dispatch binds, and at a pass every result
// of a dispatch not yet ordered is ordered before the stages its resource's usages allow.
//
// Explicit barriers (CommandList::resourceBarriers, a frame graph's declared uses) come on top: declare() gives the
// barrier between two states and opens a scope of declared uses, and covers() then tells whether an access the list
// records is among them, so that a pass that touches a resource it did not declare is reported.

#include "penumbra/rhi/Flags.hpp"
#include "penumbra/rhi/ResourceBarrier.hpp"
#include "penumbra/rhi/Resources.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>

namespace penumbra::rhi {

// Where an access happens: pipeline stages (Vulkan 1.3 section 7.1.2), in the RHI's coarser terms.
enum class Stage : std::uint16_t {
    None = 0,
    DrawIndirect = 1 << 0, // indirect arguments of draws and dispatches
    VertexInput = 1 << 1, // vertex and index buffers
    VertexShader = 1 << 2,
    FragmentShader = 1 << 3,
    Attachments = 1 << 4, // colour and depth attachments (Vulkan: fragment tests and colour output)
    ComputeShader = 1 << 5,
    Copy = 1 << 6,
    Host = 1 << 7,
};
constexpr bool enableFlags(Stage) { return true; }

// What an access reads or writes (Vulkan 1.3 section 7.1.3, access types; GL 4.5 section 7.12.2's barrier bits).
enum class Access : std::uint16_t {
    None = 0,
    IndirectRead = 1 << 0,
    VertexRead = 1 << 1, // vertex attributes
    IndexRead = 1 << 2,
    UniformRead = 1 << 3,
    SampledRead = 1 << 4,
    StorageBufferRead = 1 << 5,
    StorageBufferWrite = 1 << 6,
    StorageImageRead = 1 << 7,
    StorageImageWrite = 1 << 8,
    AttachmentRead = 1 << 9,
    AttachmentWrite = 1 << 10,
    CopyRead = 1 << 11,
    CopyWrite = 1 << 12,
    HostRead = 1 << 13,
};
constexpr bool enableFlags(Access) { return true; }

inline constexpr Access kWriteAccesses =
    Access::StorageBufferWrite | Access::StorageImageWrite | Access::AttachmentWrite | Access::CopyWrite;

// One access: the stages it happens in and what it does there.
struct Use {
    Stage stages = Stage::None;
    Access access = Access::None;

    bool writes() const { return hasFlag(access, kWriteAccesses); }
};

// Everything before in `src` (its writes made available) happens before everything after in `dst` (made visible
// to its accesses). src.access is None for an execution dependency alone (a write after reads).
struct Barrier {
    Use src;
    Use dst;

    bool empty() const { return src.stages == Stage::None; }
    // Adds another dependency to the same barrier.
    void merge(const Barrier& other);
};

// The graphics uses a resource's usages allow: where a pass may read or write it.
Use graphicsUses(const BufferDesc& desc);
Use graphicsUses(const TextureDesc& desc);

// The stages and accesses of a resource state (ResourceState flags merged).
Use stateUse(ResourceState state);
// What orders `after`'s accesses behind `before`'s: the writes of `before` made visible to `after`, or where only
// `after` writes, an execution dependency; empty where neither writes or `before` is Undefined.
Barrier stateBarrier(ResourceState before, ResourceState after);

// One command list's record of the accesses that involve compute, per resource, and of its declared states.
class HazardTracker {
public:
    // Declares a compute-side access (a dispatch's binding or its indirect arguments) to `resource`, whose graphics
    // uses are `graphics`; adds to `barrier` what must come first.
    void use(const void* resource, Use graphics, Use use, Barrier& barrier);
    // A pass begins: every dispatch's access not yet ordered is ordered before its resource's graphics uses.
    Barrier beginPass();
    // A copy reads (`use.access` CopyRead) or writes the resource: what must come first.
    Barrier copy(const void* resource, Use use);
    // The list ends: dispatches' writes to buffers become visible to the host.
    Barrier finish();
    // After submit, nothing is outstanding.
    void reset();

    // CommandList::resourceBarriers: records each resource's new state and returns the barrier they need. Opens the
    // scope of declared uses of `pass` (the innermost label open, "" without one; `labels` are open), which ends at
    // the next declare() or when that label closes.
    Barrier declare(std::span<const ResourceBarrier> barriers, std::string pass, std::size_t labels);
    // A label closed, `labels` are still open.
    void labelClosed(std::size_t labels);
    // The state the list last declared for `resource`; Undefined where it declared none.
    ResourceState declared(const void* resource) const;
    // Whether an access of `resource` as `needed` is among the declared uses: true outside a scope and for a resource
    // the list never declared; else the scope's state for it must cover `needed`.
    bool covers(const void* resource, ResourceState needed) const;
    // Inside a scope: its state for `resource` (Undefined where it does not name it) and its pass.
    ResourceState scoped(const void* resource) const;
    const std::string& scopePass() const { return scope_.pass; }

private:
    struct Scope {
        bool open = false;
        std::string pass;
        std::size_t labels = 0; // open at the declaration: the scope ends when fewer are
        std::unordered_map<const void*, ResourceState> states;
    };

    struct State {
        Use graphics; // the resource's graphics uses
        Use write; // the last dispatch's write
        Use visible; // the uses that write has been made visible to
        Use reads; // dispatch reads since that write
        bool readsOrdered = false; // those reads are ordered before graphics writes
        std::uint64_t passes = 0; // passes begun when the resource was last ordered after graphics
        bool host = false; // a buffer a dispatch wrote: the host reads it after submit
    };

    std::unordered_map<const void*, State> states_;
    std::uint64_t passes_ = 0;
    std::unordered_map<const void*, ResourceState> declared_; // the last declared state per resource
    Scope scope_;
};

} // namespace penumbra::rhi
