#pragma once

#include "penumbra/rhi/Format.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace penumbra::rhi {

class Device;
class Texture;

// A mip chain computed on the CPU, so that every backend samples the same bytes (vkCmdBlitImage and
// glGenerateMipmap filter as each driver chooses). Each level is a box filter of the level above it: a texel
// averages the texels of the level above that its area covers, weighted by the area they share (2 x 2 texels
// for even sizes; an odd size spreads over three). RGBA8_SRGB is averaged in linear light and re-encoded,
// its alpha linearly, as sampling would filter it. Rounds to nearest.
// Formats: RGBA8, RGBA8_SRGB, R8, RG8, R32F, RGBA32F; others throw Error.
// Returns `levels` levels, level 0 a copy of `level0` (tightly packed rows, row 0 at the top).
//
// With `alphaCutoff` (RGBA formats only), each level's alpha is then scaled so that the share of its texels
// whose alpha reaches the cutoff is level 0's (Castano, "Computing Alpha Mipmaps", 2010): box-filtered alpha
// of an alpha-tested texture (leaves, fences) falls below the cutoff at thin parts, so the surface and its
// shadow would thin out and vanish with distance. Each level is filtered from the unscaled level above it.
std::vector<std::vector<std::byte>> generateMipChain(Format format, std::uint32_t width, std::uint32_t height,
                                                     std::uint32_t levels, std::span<const std::byte> level0,
                                                     std::optional<float> alphaCutoff = std::nullopt);

class MipLevels;

// The levels below level 0 of generateMipChain's chain, the same bytes, without a copy of level 0: what uploading a
// texture needs (a large texture's chain no longer holds its level 0 twice).
MipLevels generateMipLevels(Format format, std::uint32_t width, std::uint32_t height, std::uint32_t levels,
                            std::span<const std::byte> level0, std::optional<float> alphaCutoff = std::nullopt);

// Levels 1 to levels - 1 of a mip chain (level 0 is the caller's), written in place into one allocation.
class MipLevels {
public:
    // The levels of the chain, level 0 included (0 for a MipLevels made empty, which holds none).
    std::uint32_t levels() const { return std::uint32_t(offsets_.size()); }
    // The bytes of `level`, 1 to levels() - 1.
    std::span<const std::byte> level(std::uint32_t level) const;

private:
    friend MipLevels generateMipLevels(Format, std::uint32_t, std::uint32_t, std::uint32_t, std::span<const std::byte>,
                                       std::optional<float>);
    std::unique_ptr<std::byte[]> bytes_;
    std::vector<std::size_t> offsets_; // level l's bytes are [offsets_[l - 1], offsets_[l])
};

// Fills every mip level of `layer`: level 0 from `level0`, the others generated from it by generateMipChain.
void writeMipChain(Device& device, Texture& texture, std::uint32_t layer, std::span<const std::byte> level0,
                   std::optional<float> alphaCutoff = std::nullopt);

} // namespace penumbra::rhi
