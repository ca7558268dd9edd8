#pragma once

#include "penumbra/rhi/Resources.hpp"

#include <cstdint>
#include <glm/mat4x4.hpp>

namespace penumbra::shadows {

// How a caster's surface enters the atlas; casters that cast nothing are simply not listed.
enum class ShadowCasterMode : std::uint8_t {
    Opaque, // every texel
    Clip,   // texels whose alpha (with the clip checker, material.glsl) is below alphaCutoff are dropped
    Dither, // a texel is kept where alpha reaches the interleaved-gradient dither (alpha as coverage)
};

// Where position and uv sit in the caster's vertices (float3 and float2).
struct CasterVertexFormat {
    std::uint32_t stride = 0;
    std::uint32_t positionOffset = 0;
    std::uint32_t uvOffset = 0;
};

// One indexed mesh instance that casts shadows. A frame's casters are listed in the same order as
// the caster bounds given to planDirectionalShadows, whose per-cascade lists index them.
struct ShadowCaster {
    const rhi::Buffer* vertices = nullptr;
    const rhi::Buffer* indices = nullptr; // 32-bit indices
    std::uint32_t indexCount = 0;
    glm::mat4 model{1.0f};
    ShadowCasterMode mode = ShadowCasterMode::Opaque;
    float alpha = 1.0f;
    float alphaCutoff = 0.5f;
    // Clip and Dither casters read their alpha through these (binding 1 of shadow_caster_alpha.frag):
    // the base colour texture when `textured`, else any texture (a white texel).
    const rhi::Texture* baseColorMap = nullptr;
    const rhi::Sampler* baseColorSampler = nullptr;
    bool textured = false;
};

} // namespace penumbra::shadows
