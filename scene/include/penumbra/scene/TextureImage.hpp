#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace penumbra::scene {

enum class TextureFilter : std::uint8_t { Nearest, Linear };
// Between mip levels: None reads the full-size picture only.
enum class TextureMipFilter : std::uint8_t { None, Nearest, Linear };
enum class TextureWrap : std::uint8_t { Repeat, ClampToEdge, MirroredRepeat };

// How a texture is sampled: glTF's sampler. The defaults are glTF's for a texture without one (repeat, and the
// "auto" filtering it leaves to the renderer: trilinear).
struct TextureSampler {
    TextureFilter magFilter = TextureFilter::Linear;
    TextureFilter minFilter = TextureFilter::Linear;
    TextureMipFilter mipFilter = TextureMipFilter::Linear;
    TextureWrap wrapS = TextureWrap::Repeat; // along u
    TextureWrap wrapT = TextureWrap::Repeat; // along v
};

// Colour textures (base colour, emissive) hold sRGB-encoded colour, data textures linear values (glTF 2.0,
// section 3.9, materials); the GPU decodes sRGB when it samples.
enum class TextureColorSpace : std::uint8_t { Srgb, Linear };

// A decoded texture: RGBA8, 4 bytes per texel, row 0 at the top (v = 0, as in the RHI and in
// image files), colour channels as stored in the file. Its mip levels are made when it is uploaded.
struct TextureImage {
    std::string name;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> rgba; // width * height * 4 bytes
    TextureColorSpace colorSpace = TextureColorSpace::Srgb;
    TextureSampler sampler;
};

} // namespace penumbra::scene
