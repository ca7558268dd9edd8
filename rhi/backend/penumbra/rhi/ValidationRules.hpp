#pragma once

// For backends: the rules of the validation layer that a backend's own objects apply (Buffer::write and read
// are calls on the buffer, not on the device) and rhi's own helpers (readTexture). Everything else is checked by
// ValidatingDevice.hpp's classes.

#include "penumbra/rhi/Resources.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace penumbra::rhi {

// `what` (a call) addresses `size` bytes at `offset` of the buffer: they must lie inside it.
void checkBufferRange(std::string_view what, const BufferDesc& buffer, std::uint64_t offset, std::uint64_t size);

// Buffer::write and Buffer::read on persistently mapped memory (`mapped`: the buffer's first byte): the range is
// checked, then the bytes copied. An empty span copies nothing, since an empty buffer maps to no memory and memcpy
// takes no null pointer even for 0 bytes.
void writeMappedBuffer(const BufferDesc& buffer, std::byte* mapped, std::uint64_t offset,
                       std::span<const std::byte> data);
void readMappedBuffer(const BufferDesc& buffer, const std::byte* mapped, std::uint64_t offset,
                      std::span<std::byte> data);

// `what` addresses level `level` of layer `layer`: both must exist.
void checkSubresource(std::string_view what, const TextureDesc& desc, std::uint32_t layer, std::uint32_t level);

} // namespace penumbra::rhi
