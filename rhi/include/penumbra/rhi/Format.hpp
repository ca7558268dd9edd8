#pragma once

#include <cstdint>
#include <string_view>

namespace penumbra::rhi {

enum class Format : std::uint8_t {
    RGBA8,   // unsigned normalised, linear (no sRGB conversion)
    RGBA16F,
    RGBA32F,
    D16,     // unsigned normalised 16-bit depth
    D24S8,   // unsigned normalised 24-bit depth, 8-bit stencil
    D32F,    // 32-bit float depth
};

constexpr bool isDepthFormat(Format f) { return f == Format::D16 || f == Format::D24S8 || f == Format::D32F; }

// Bytes of one texel as the RHI copies it to a buffer; for D24S8 only the depth aspect
// is copied, as a 32-bit word whose low 24 bits hold the depth.
constexpr std::uint32_t texelSize(Format f)
{
    switch (f) {
    case Format::RGBA8: return 4;
    case Format::RGBA16F: return 8;
    case Format::RGBA32F: return 16;
    case Format::D16: return 2;
    case Format::D24S8: return 4;
    case Format::D32F: return 4;
    }
    return 0;
}

std::string_view formatName(Format f);

} // namespace penumbra::rhi
