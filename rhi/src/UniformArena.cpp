#include "penumbra/rhi/UniformArena.hpp"

#include "penumbra/rhi/Device.hpp"

#include <algorithm>

namespace penumbra::rhi {

UniformArena::UniformArena(Device& device, std::string debugName)
    : device_(device), debugName_(std::move(debugName)),
      alignment_(std::max<std::uint64_t>(device.capabilities().uniformBufferOffsetAlignment, 16))
{
}

void UniformArena::reset()
{
    retired_.clear();
    used_ = 0;
}

UniformSlice UniformArena::push(std::span<const std::byte> data)
{
    const std::uint64_t offset = (used_ + alignment_ - 1) / alignment_ * alignment_;
    const std::uint64_t capacity = current_ ? current_->desc().size : 0;
    if (offset + data.size() > capacity) {
        const std::uint64_t size = std::max<std::uint64_t>({capacity * 2, 64 * 1024, data.size()});
        if (current_)
            retired_.push_back(std::move(current_));
        current_ = device_.createBuffer({.size = size, .usage = BufferUsage::Uniform, .debugName = debugName_});
        used_ = 0;
        return push(data);
    }
    current_->write(offset, data);
    used_ = offset + data.size();
    return {current_.get(), offset, data.size()};
}

void bindUniform(CommandList& commands, std::uint32_t binding, const UniformSlice& slice)
{
    commands.bindUniformBuffer(binding, *slice.buffer, slice.offset, slice.size);
}

} // namespace penumbra::rhi
