#include "penumbra/rhi/BackendSupport.hpp"
#include "penumbra/rhi/ValidationRules.hpp"
#include "penumbra/rhi/Device.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/Image.hpp"

#include <cstring>
#include <fmt/format.h>

namespace penumbra::rhi {

Image readTexture(Device& device, const Texture& texture, std::uint32_t layer, std::uint32_t level)
{
    const TextureDesc& desc = texture.desc();
    checkSubresource("readTexture", desc, layer, level);
    const std::uint64_t size = levelSize(desc, level);
    auto buffer = device.createBuffer({.size = size, .usage = BufferUsage::Readback, .debugName = "readback"});
    auto commands = device.createCommandList();
    commands->copyTextureToBuffer(texture, layer, level, *buffer);
    device.submit(*commands);

    Image image{mipExtent(desc.width, level), mipExtent(desc.height, level), desc.format, std::vector<std::byte>(size)};
    buffer->read(0, image.bytes);
    return image;
}

DepthImage readDepth(Device& device, const Texture& texture, std::uint32_t layer)
{
    const Format format = texture.desc().format;
    if (!isDepthFormat(format))
        throw Error(
            fmt::format("readDepth: '{}' is {}, not a depth format", texture.desc().debugName, formatName(format)));
    const Image raw = readTexture(device, texture, layer);
    DepthImage out{raw.width, raw.height, std::vector<float>(std::size_t(raw.width) * raw.height)};
    for (std::size_t i = 0; i < out.depth.size(); ++i) {
        const std::byte* p = raw.bytes.data() + i * texelSize(format);
        if (format == Format::D16) {
            std::uint16_t v;
            std::memcpy(&v, p, sizeof v);
            out.depth[i] = float(v) / 65535.0f;
        } else if (format == Format::D24S8) {
            std::uint32_t v;
            std::memcpy(&v, p, sizeof v);
            out.depth[i] = float(double(v & 0xFFFFFFu) / 16777215.0);
        } else {
            std::memcpy(&out.depth[i], p, sizeof(float));
        }
    }
    return out;
}

} // namespace penumbra::rhi
