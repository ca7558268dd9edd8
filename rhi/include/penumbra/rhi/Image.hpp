#pragma once

#include "penumbra/rhi/Format.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace penumbra::rhi {

class Device;
class Texture;

// A texture layer read back to the CPU: tightly packed rows, row 0 is the top of the picture.
struct Image {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    Format format = Format::RGBA8;
    std::vector<std::byte> bytes;

    // The bytes of texel (x, y), row 0 at the top.
    const std::byte* texel(std::uint32_t x, std::uint32_t y) const
    {
        return bytes.data() + (std::size_t(y) * width + x) * texelSize(format);
    }
};

// Window-space depth in [0, 1], decoded exactly from D16, D24S8 or D32F; row 0 is the top.
struct DepthImage {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<float> depth;

    // Depth of texel (x, y), row 0 at the top.
    float at(std::uint32_t x, std::uint32_t y) const { return depth[std::size_t(y) * width + x]; }
};

// Copies one mip level of one layer into a readback buffer, submits and waits.
Image readTexture(Device& device, const Texture& texture, std::uint32_t layer = 0, std::uint32_t level = 0);
// Depth textures only: the raw values decoded to float (d16 / 65535, d24 / 16777215, d32f as is).
DepthImage readDepth(Device& device, const Texture& texture, std::uint32_t layer = 0);

} // namespace penumbra::rhi
