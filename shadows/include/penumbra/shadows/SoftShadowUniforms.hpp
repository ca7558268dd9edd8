#pragma once

#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <array>
#include <cstddef>
#include <cstdint>

namespace penumbra::shadows {

// SoftShadowSettings as the lit shader's blocks carry them: the GLSL struct SoftControls (soft_shadows.glsl).
struct alignas(16) SoftShadowUniforms {
    float searchScale = 0.0f; // SoftShadowSettings::blockerSearchScale
    float penumbraScale = 0.0f;
    float minTexels = 0.0f; // the penumbra's clamp, in texels
    float maxTexels = 0.0f;
    std::int32_t blockerSamples = 0;
    std::int32_t filterSamples = 0;
    float poissonRadius = 0.0f; // texels
};

inline constexpr std::array kSoftShadowFields{
    PENUMBRA_SHADER_FIELD(SoftShadowUniforms, searchScale),    PENUMBRA_SHADER_FIELD(SoftShadowUniforms, penumbraScale),
    PENUMBRA_SHADER_FIELD(SoftShadowUniforms, minTexels),      PENUMBRA_SHADER_FIELD(SoftShadowUniforms, maxTexels),
    PENUMBRA_SHADER_FIELD(SoftShadowUniforms, blockerSamples), PENUMBRA_SHADER_FIELD(SoftShadowUniforms, filterSamples),
    PENUMBRA_SHADER_FIELD(SoftShadowUniforms, poissonRadius),
};
inline constexpr shaders::ShaderStruct kSoftShadowStruct{"SoftControls", sizeof(SoftShadowUniforms), kSoftShadowFields};
static_assert(shaders::matchesLayout(kSoftShadowStruct, shaders::BlockLayout::Std140, true));

SoftShadowUniforms softShadowUniforms(const SoftShadowSettings& soft);

// tan of half a directional light's angular diameter (degrees).
float tanHalfAngularDiameter(float degrees);

} // namespace penumbra::shadows
