#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace penumbra::rhi {

enum class Format : std::uint8_t {
    RGBA8, // unsigned normalised, linear (no sRGB conversion)
    RGBA16F,
    RGBA32F,
    D16, // unsigned normalised 16-bit depth
    D24S8, // unsigned normalised 24-bit depth, 8-bit stencil
    D32F, // 32-bit float depth
    // sRGB-encoded colour, linear alpha: sampling decodes to linear light before filtering, rendering
    // encodes (Vulkan 1.3, "Format Conversion" of texel input; GL 4.5 section 8.24); copies and readbacks move
    // the encoded bytes.
    RGBA8_SRGB,
    R8, // unsigned normalised; sampled as (r, 0, 0, 1)
    RG8, // unsigned normalised; sampled as (r, g, 0, 1)
    R16F,
    RG16F,
    R32F,
};

inline constexpr std::array allFormats{Format::RGBA8, Format::RGBA16F, Format::RGBA32F,    Format::D16,
                                       Format::D24S8, Format::D32F,    Format::RGBA8_SRGB, Format::R8,
                                       Format::RG8,   Format::R16F,    Format::RG16F,      Format::R32F};
inline constexpr std::size_t formatCount = allFormats.size();

constexpr bool isDepthFormat(Format f) { return f == Format::D16 || f == Format::D24S8 || f == Format::D32F; }
constexpr bool isSrgbFormat(Format f) { return f == Format::RGBA8_SRGB; }

// Bytes of one texel as the RHI copies it to a buffer; for D24S8 only the depth aspect
// is copied, as a 32-bit word whose low 24 bits hold the depth.
constexpr std::uint32_t texelSize(Format f)
{
    switch (f) {
    case Format::RGBA8:
        return 4;
    case Format::RGBA16F:
        return 8;
    case Format::RGBA32F:
        return 16;
    case Format::D16:
        return 2;
    case Format::D24S8:
        return 4;
    case Format::D32F:
        return 4;
    case Format::RGBA8_SRGB:
        return 4;
    case Format::R8:
        return 1;
    case Format::RG8:
        return 2;
    case Format::R16F:
        return 2;
    case Format::RG16F:
        return 4;
    case Format::R32F:
        return 4;
    }
    return 0;
}

std::string_view formatName(Format f);

} // namespace penumbra::rhi
