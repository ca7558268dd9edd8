#pragma once

#include "penumbra/rhi/Resources.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace penumbra::rhi {

class CommandList;
class Device;

// A range of an arena's buffer.
struct BufferSlice {
    const Buffer* buffer = nullptr;
    std::uint64_t offset = 0;
    std::uint64_t size = 0;
};
// A range of a uniform buffer, aligned for bindUniformBuffer.
using UniformSlice = BufferSlice;

// Data of one submission packed into buffers of one usage, each slice aligned to `alignment`. The buffer grows by
// doubling; a full buffer is kept alive until reset(), since recorded draws still name it. Call reset() only after
// the lists that bound earlier slices were submitted.
class BufferArena {
public:
    // An arena of `usage` buffers on `device` whose slices start at multiples of `alignment`.
    BufferArena(Device& device, std::string debugName, BufferUsage usage, std::uint64_t alignment);

    // Forgets every slice: the next push starts at the beginning (after a submission).
    void reset();
    // Copies `data` into the arena and returns where it went.
    BufferSlice push(std::span<const std::byte> data);

    template <typename T>
    // Copies one trivially copyable value into the arena.
    BufferSlice push(const T& value)
    {
        return push(std::as_bytes(std::span(&value, 1)));
    }

private:
    Device& device_;
    std::string debugName_;
    BufferUsage usage_;
    std::uint64_t alignment_;
    std::unique_ptr<Buffer> current_;
    std::vector<std::unique_ptr<Buffer>> retired_;
    std::uint64_t used_ = 0;
};

// Uniform data of one submission (per-draw matrices, per-frame blocks), each slice aligned to
// Capabilities::uniformBufferOffsetAlignment.
class UniformArena : public BufferArena {
public:
    // An arena of uniform buffers aligned to the device's uniform offset alignment.
    UniformArena(Device& device, std::string debugName);
};

// Per-instance vertex data of one submission (instance transforms), bound with bindVertexBuffer at a slice's offset.
class VertexArena : public BufferArena {
public:
    // An arena of vertex buffers, for per-instance data.
    VertexArena(Device& device, std::string debugName);
};

void bindUniform(CommandList& commands, std::uint32_t binding, const UniformSlice& slice);

} // namespace penumbra::rhi
