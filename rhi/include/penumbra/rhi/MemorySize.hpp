#pragma once

#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/Resources.hpp"

#include <cstdint>
#include <string>

namespace penumbra::rhi {

// Bytes a texture's texels take: every mip level of every layer at Format's texelSize (what the driver allocates
// is at least this; it may pad rows and align levels).
std::uint64_t textureBytes(const TextureDesc& desc);

// "512 B", "256.0 MiB", "1.5 GiB": for messages.
std::string byteSize(std::uint64_t bytes);

// "texture 'atlas' (8192 x 8192, 6 layers, D32F, 1.5 GiB)" and "buffer 'vertices' (1.0 MiB)": how an
// out-of-memory error names what was asked for.
std::string describeAllocation(const TextureDesc& desc);
std::string describeAllocation(const BufferDesc& desc);

// Throws Error "<description> does not fit in the device's <size> of memory" when `bytes` is more than
// Capabilities::deviceMemoryBytes (where the device reports it).
void checkFitsInMemory(const Capabilities& caps, const std::string& description, std::uint64_t bytes);

} // namespace penumbra::rhi
