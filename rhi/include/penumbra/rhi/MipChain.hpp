#pragma once

#include "penumbra/rhi/Format.hpp"

#include <cstddef>
#include <cstdint>
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
std::vector<std::vector<std::byte>> generateMipChain(Format format, std::uint32_t width, std::uint32_t height,
                                                     std::uint32_t levels, std::span<const std::byte> level0);

// Fills every mip level of `layer`: level 0 from `level0`, the others generated from it by generateMipChain.
void writeMipChain(Device& device, Texture& texture, std::uint32_t layer, std::span<const std::byte> level0);

} // namespace penumbra::rhi
