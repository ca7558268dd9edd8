#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace penumbra::gltf {

// A PNG picture decoded to RGBA8, as the scene keeps textures.
struct PngPicture {
    std::uint32_t width = 0, height = 0;
    std::vector<unsigned char> rgba;
};

// Decodes a PNG of any colour type, bit depth and interlace with libpng, a row at a time straight into the RGBA8
// texels: palette and grey expanded to RGB, a tRNS chunk to alpha, a missing alpha opaque, 16-bit channels rounded
// to nearest (libpng's png_set_scale_16). Colour-space chunks (gAMA, cHRM, iCCP, sRGB) change no texel, as glTF
// 2.0 section 3.8.1 asks, and chunk checksums are not checked (the texels are the same either way).
// Throws std::runtime_error saying what is wrong, as a phrase after "the picture": "does not decode: libpng: " and
// libpng's message, or that it is over the loader's limits (kMaxImageSide, kMaxImageTexels), checked before any
// texel is decoded.
PngPicture decodePng(std::span<const std::uint8_t> bytes);

} // namespace penumbra::gltf
