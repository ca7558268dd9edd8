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

// A range of a uniform buffer, aligned for bindUniformBuffer.
struct UniformSlice {
    const Buffer* buffer = nullptr;
    std::uint64_t offset = 0;
    std::uint64_t size = 0;
};

// Uniform data of one submission (per-draw matrices, per-frame blocks) packed into one buffer,
// each slice aligned to Capabilities::uniformBufferOffsetAlignment. The buffer grows by
// doubling; a full buffer is kept alive until reset(), since recorded draws still name it.
// Call reset() only after the lists that bound earlier slices were submitted.
class UniformArena {
public:
    UniformArena(Device& device, std::string debugName);

    void reset();
    UniformSlice push(std::span<const std::byte> data);

    template <typename T>
    UniformSlice push(const T& value)
    {
        return push(std::as_bytes(std::span(&value, 1)));
    }

private:
    Device& device_;
    std::string debugName_;
    std::uint64_t alignment_;
    std::unique_ptr<Buffer> current_;
    std::vector<std::unique_ptr<Buffer>> retired_;
    std::uint64_t used_ = 0;
};

void bindUniform(CommandList& commands, std::uint32_t binding, const UniformSlice& slice);

} // namespace penumbra::rhi
