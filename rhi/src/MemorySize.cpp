#include "penumbra/rhi/MemorySize.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>

namespace penumbra::rhi {

std::uint64_t textureBytes(const TextureDesc& desc)
{
    std::uint64_t texels = 0;
    for (std::uint32_t level = 0; level < desc.mipLevels; ++level)
        texels += std::uint64_t(mipExtent(desc.width, level)) * mipExtent(desc.height, level);
    return texels * desc.layers * texelSize(desc.format);
}

std::string byteSize(std::uint64_t bytes)
{
    constexpr double kKiB = 1024.0;
    if (bytes < 1024)
        return fmt::format("{} B", bytes);
    if (double(bytes) < kKiB * kKiB)
        return fmt::format("{:.1f} KiB", double(bytes) / kKiB);
    if (double(bytes) < kKiB * kKiB * kKiB)
        return fmt::format("{:.1f} MiB", double(bytes) / (kKiB * kKiB));
    return fmt::format("{:.1f} GiB", double(bytes) / (kKiB * kKiB * kKiB));
}

std::string describeAllocation(const TextureDesc& desc)
{
    return fmt::format("texture '{}' ({} x {}{}{}, {}, {})", desc.debugName, desc.width, desc.height,
                       desc.layers > 1 ? fmt::format(", {} layers", desc.layers) : "",
                       desc.mipLevels > 1 ? fmt::format(", {} levels", desc.mipLevels) : "", formatName(desc.format),
                       byteSize(textureBytes(desc)));
}

std::string describeAllocation(const BufferDesc& desc)
{
    return fmt::format("buffer '{}' ({})", desc.debugName, byteSize(desc.size));
}

void checkFitsInMemory(const Capabilities& caps, const std::string& description, std::uint64_t bytes)
{
    if (caps.deviceMemoryBytes != 0 && bytes > caps.deviceMemoryBytes)
        throw Error(
            fmt::format("{} does not fit in the device's {} of memory", description, byteSize(caps.deviceMemoryBytes)));
}

} // namespace penumbra::rhi
