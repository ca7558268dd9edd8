#pragma once

#include "penumbra/rhi/Format.hpp"

#include <cstddef>
#include <cstdint>
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

// Fills every mip level of `layer`: level 0 from `level0`, the others generated from it by generateMipChain.
void writeMipChain(Device& device, Texture& texture, std::uint32_t layer, std::span<const std::byte> level0,
                   std::optional<float> alphaCutoff = std::nullopt);

} // namespace penumbra::rhi
