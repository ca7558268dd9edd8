#pragma once

#include "penumbra/rhi/Flags.hpp"

#include <cstdint>
#include <string>

namespace penumbra::rhi {

class Buffer;
class Texture;

// How commands use a resource, for CommandList::resourceBarriers: Direct3D 12's resource states ("Using Resource
// Barriers to Synchronize Resource States in Direct3D 12"), each standing for Vulkan's stages and accesses (Vulkan 1.3
// section 7.1, "Execution and Memory Dependencies"). Flags: a resource may be in several read states at once.
enum class ResourceState : std::uint16_t {
    Undefined = 0, // as `before`: the list has not declared the resource yet
    VertexBuffer = 1 << 0,
    IndexBuffer = 1 << 1,
    IndirectArgument = 1 << 2, // indirect draw and dispatch arguments and their counts
    UniformBuffer = 1 << 3,
    ShaderRead = 1 << 4, // sampled textures and storage buffers and images read, in any shader stage
    ShaderWrite = 1 << 5, // storage buffers and images written (and read) by compute shaders
    RenderTarget = 1 << 6, // a colour or depth attachment drawn into (and read: blending, depth tests)
    DepthRead = 1 << 7, // a depth attachment tested but not written
    CopySource = 1 << 8, // read by a copy, a resolve or a readback
    CopyDestination = 1 << 9, // written by a copy or a resolve
};
constexpr bool enableFlags(ResourceState) { return true; }

// The states' names joined by " | " ("ShaderRead | DepthRead"), or "Undefined".
std::string resourceStateName(ResourceState state);

// One resource leaving the state the list's earlier commands used it in for the state its next commands use it in.
struct ResourceBarrier {
    const Texture* texture = nullptr; // exactly one of texture and buffer
    const Buffer* buffer = nullptr;
    ResourceState before = ResourceState::Undefined; // what the list last declared for it; Undefined the first time
    ResourceState after = ResourceState::Undefined;

    static ResourceBarrier of(const Texture& texture, ResourceState before, ResourceState after)
    {
        return {&texture, nullptr, before, after};
    }
    static ResourceBarrier of(const Buffer& buffer, ResourceState before, ResourceState after)
    {
        return {nullptr, &buffer, before, after};
    }
};

} // namespace penumbra::rhi
