#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace penumbra::scene {

// A decoded texture: RGBA8, 4 bytes per texel, row 0 at the top (v = 0, as in the RHI and in
// image files), colour channels as stored in the file (sRGB-encoded for base colour textures).
struct TextureImage {
    std::string name;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> rgba; // width * height * 4 bytes
};

} // namespace penumbra::scene
