#pragma once

#include "penumbra/rhi/ResourceBarrier.hpp"

#include <vector>

namespace penumbra::render {

// A pass's use of one texture or buffer: the state it needs the object in.
struct ObjectUse {
    const void* object = nullptr;
    rhi::ResourceState state = rhi::ResourceState::Undefined;
};

// An object's move from the state earlier passes left it in to the state a pass needs.
struct StateChange {
    const void* object = nullptr;
    rhi::ResourceState before = rhi::ResourceState::Undefined;
    rhi::ResourceState after = rhi::ResourceState::Undefined;
    bool operator==(const StateChange&) const = default;
};

// The state changes before each of a frame's passes (`passes`: each pass's uses, in running order; every object starts
// Undefined): a change per object a pass uses, its uses' states merged. Where a pass waits on a shader write anyway
// (a change out of ShaderWrite), the later passes' waits on other shader writes join it, each object's at its next use
// (nothing uses it in between): one barrier instead of one per reading pass, which matters where a driver makes each a
// whole finish (Mesa's llvmpipe: llvmpipe_memory_barrier calls llvmpipe_finish, src/gallium/drivers/llvmpipe/
// lp_texture.c). The pass that then uses the object still declares it, with no change.
// Batching the barriers a graph derives: O'Donnell, "FrameGraph: Extensible Rendering Architecture in Frostbite", GDC
// 2017.
std::vector<std::vector<StateChange>> passBarriers(const std::vector<std::vector<ObjectUse>>& passes);

} // namespace penumbra::render
