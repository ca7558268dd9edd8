#include "penumbra/rhi/UniformArena.hpp"

#include "penumbra/rhi/CommandList.hpp"
#include "penumbra/rhi/Device.hpp"

#include <algorithm>

namespace penumbra::rhi {

BufferArena::BufferArena(Device& device, std::string debugName, BufferUsage usage, std::uint64_t alignment)
    : device_(device), debugName_(std::move(debugName)), usage_(usage), alignment_(alignment)
{
}

void BufferArena::reset()
{
    retired_.clear();
    used_ = 0;
}

BufferSlice BufferArena::push(std::span<const std::byte> data)
{
    const std::uint64_t offset = (used_ + alignment_ - 1) / alignment_ * alignment_;
    const std::uint64_t capacity = current_ ? current_->desc().size : 0;
    if (offset + data.size() > capacity) {
        const std::uint64_t size = std::max<std::uint64_t>({capacity * 2, 64 * 1024, data.size()});
        if (current_)
            retired_.push_back(std::move(current_));
        current_ = device_.createBuffer({.size = size, .usage = usage_, .debugName = debugName_});
        used_ = 0;
        return push(data);
    }
    current_->write(offset, data);
    used_ = offset + data.size();
    return {current_.get(), offset, data.size()};
}

UniformArena::UniformArena(Device& device, std::string debugName)
    : BufferArena(device, std::move(debugName), BufferUsage::Uniform,
                  std::max<std::uint64_t>(device.capabilities().uniformBufferOffsetAlignment, 16))
{
}

// Vertex buffer offsets need only their attributes' alignment (the Vulkan specification, "Vertex Input Address
// Calculation"); 16 keeps every vec4 of a slice aligned.
VertexArena::VertexArena(Device& device, std::string debugName)
    : BufferArena(device, std::move(debugName), BufferUsage::Vertex, 16)
{
}

void bindUniform(CommandList& commands, std::uint32_t binding, const UniformSlice& slice)
{
    commands.bindUniformBuffer(binding, *slice.buffer, slice.offset, slice.size);
}

} // namespace penumbra::rhi
