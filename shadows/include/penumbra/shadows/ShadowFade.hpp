#pragma once

#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <array>
#include <cstddef>

namespace penumbra::shadows {

// The lit shader's reciprocals for fadedShadowStrength, the GLSL struct ShadowDistanceFade of the block
// DirectionalShadows. The stable fit's cascade fade is taken on squared distance (the selection already has it), so
// the fraction f becomes 1 - (1 - f)^2 to keep the same fade band; the close fit's on view depth, linear like the
// distance fade.
struct alignas(16) ShadowDistanceFade {
    float inverseMaxDistance = 0.0f; // 1 / maxDistance
    float inverseDistanceFade = 0.0f; // 1 / distanceFade
    float inverseSphereCascadeFade = 0.0f; // 1 / (1 - (1 - cascadeFade)^2): the stable fit's
    float inverseDepthCascadeFade = 0.0f; // 1 / cascadeFade: the close fit's
};

inline constexpr std::array kShadowDistanceFadeFields{
    PENUMBRA_SHADER_FIELD(ShadowDistanceFade, inverseMaxDistance),
    PENUMBRA_SHADER_FIELD(ShadowDistanceFade, inverseDistanceFade),
    PENUMBRA_SHADER_FIELD(ShadowDistanceFade, inverseSphereCascadeFade),
    PENUMBRA_SHADER_FIELD(ShadowDistanceFade, inverseDepthCascadeFade),
};
inline constexpr shaders::ShaderStruct kShadowDistanceFadeStruct{"ShadowDistanceFade", sizeof(ShadowDistanceFade),
                                                                 kShadowDistanceFadeFields};
static_assert(shaders::matchesLayout(kShadowDistanceFadeStruct, shaders::BlockLayout::Std140, true));

ShadowDistanceFade shadowDistanceFade(const ShadowSettings& settings);

// saturate((1 - distance * scale) * fade): 1 inside, falling linearly to 0 at distance = 1 / scale.
float fadedShadowStrength(float distance, float scale, float fade);

} // namespace penumbra::shadows
