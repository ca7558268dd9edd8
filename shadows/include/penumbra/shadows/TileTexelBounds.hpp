#pragma once

#include "penumbra/shaders/ShaderBlock.hpp"

#include <array>
#include <cstddef>
#include <glm/vec2.hpp>

namespace penumbra::shadows {

// The first and last texel of an atlas tile (ShadowAtlasLayout::tileTexelBounds): the texels its filter taps may
// read, clamped to in the shader (shadow_filter.glsl) instead of worked out per pixel with an integer division
// (llvmpipe has no vector one). The GLSL struct TileTexelBounds of the shadow blocks.
struct alignas(16) TileTexelBounds {
    glm::ivec2 first{0};
    glm::ivec2 last{0};

    bool operator==(const TileTexelBounds&) const = default;
};

inline constexpr std::array kTileTexelBoundsFields{
    PENUMBRA_SHADER_FIELD(TileTexelBounds, first),
    PENUMBRA_SHADER_FIELD(TileTexelBounds, last),
};
inline constexpr shaders::ShaderStruct kTileTexelBoundsStruct{"TileTexelBounds", sizeof(TileTexelBounds),
                                                              kTileTexelBoundsFields};
static_assert(shaders::matchesLayout(kTileTexelBoundsStruct, shaders::BlockLayout::Std140, true));
static_assert(shaders::matchesLayout(kTileTexelBoundsStruct, shaders::BlockLayout::Std430, true));

} // namespace penumbra::shadows
