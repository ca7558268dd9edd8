#pragma once

#include "penumbra/rhi/Resources.hpp"
#include "penumbra/shadows/InstanceBatches.hpp"

#include <array>
#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace penumbra::shadows {

// How a caster's surface enters the atlas; casters that cast nothing are simply not listed.
enum class ShadowCasterMode : std::uint8_t {
    Opaque, // every texel
    Clip, // texels whose alpha (with the clip checker, material.glsl) is below alphaCutoff are dropped
    Dither, // a texel is kept where alpha reaches the interleaved-gradient dither (alpha as coverage)
};

// Where position, normal and the two uv sets sit in the caster's vertices (float3, float3, float2, float2).
struct CasterVertexFormat {
    std::uint32_t stride = 0;
    std::uint32_t positionOffset = 0;
    std::uint32_t normalOffset = 0;
    std::uint32_t uvOffset = 0;
    std::uint32_t uv1Offset = 0;
};

// A texture's uv transform (KHR_texture_transform) and uv set as shaders read it (material.glsl's
// transformedUv): rows 0 and 1 of the 3 x 3 matrix, row 0's w the uv set (0 or 1).
using UvTransformRows = std::array<glm::vec4, 2>;
UvTransformRows uvTransformRows(const glm::mat3& transform, std::uint32_t uvSet);

// One indexed mesh instance that casts shadows. A frame's casters are listed in the same order as
// the caster bounds given to planDirectionalShadows, whose per-cascade lists index them.
struct ShadowCaster {
    const rhi::Buffer* vertices = nullptr;
    const rhi::Buffer* indices = nullptr; // 32-bit indices
    std::uint32_t indexCount = 0;
    glm::mat4 model{1.0f};
    // What the vertices were deformed to this frame (a skinned or morphed mesh's pose, as a hash), 0 for vertices that
    // never change: the tile caches redraw a tile whose caster's pose changed although its model did not.
    std::uint64_t pose = 0;
    ShadowCasterMode mode = ShadowCasterMode::Opaque;
    float alpha = 1.0f;
    float alphaCutoff = 0.5f;
    // Clip and Dither casters read their alpha through these (binding 1 of shadow_caster_alpha.frag):
    // the base colour texture when `textured`, else any texture (a white texel).
    const rhi::Texture* baseColorMap = nullptr;
    const rhi::Sampler* baseColorSampler = nullptr;
    bool textured = false;
    UvTransformRows baseColorUv = uvTransformRows(glm::mat3(1.0f), 0); // where the base colour texture is read
    // Drawn without culling, so both faces cast (glTF doubleSided); single-sided casters cast their
    // light-facing side.
    bool doubleSided = false;
    // Casters of one draw group share everything above but `model` and are drawn as the instances of one draw
    // (ShadowCasterDraws refuses a group whose casters differ); kNoDrawGroup draws the caster alone.
    std::uint32_t drawGroup = kNoDrawGroup;
};

// Whether two casters draw alike but for their model matrices: what casters of one draw group must.
bool drawAlike(const ShadowCaster& a, const ShadowCaster& b);

} // namespace penumbra::shadows
