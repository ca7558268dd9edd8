#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace penumbra::gltf {

// The texels of a PNG of 8-bit truecolour, with or without alpha, not interlaced (the pictures glTF files mostly
// carry), as RGBA8, a missing alpha opaque: inflated by zlib a row at a time and unfiltered straight into the texels
// (W3C PNG, second edition, sections 9 and 10). stb_image's inflate, and its whole-picture buffers and their page
// faults, were most of loading a dozen 2048 x 2048 textures (docs/notes/2026-12-06-large-texture-loading.md).
// Nothing for any other PNG (another colour type or depth, interlaced, a tRNS or PLTE chunk, an unknown critical
// chunk) or one that does not inflate to exactly its rows: stb_image decodes those, or says what is wrong. PNG is
// lossless, so both give the same texels.
std::optional<std::vector<unsigned char>> decodeTruecolourPng(std::span<const std::uint8_t> bytes);

} // namespace penumbra::gltf
