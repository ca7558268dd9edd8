#pragma once

#include "penumbra/rhi/UniformLayout.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <cstddef>
#include <vector>

#include <glm/vec4.hpp>

namespace penumbra::shadows {

// SoftShadowSettings as the lit shader's blocks carry them (two vec4s, std140).
struct SoftShadowUniforms {
    glm::vec4 scales{0.0f}; // blockerSearchScale, penumbraScale, minPenumbraTexels, maxPenumbraTexels
    glm::vec4 counts{0.0f}; // blockerSamples, filterSamples, poissonRadiusTexels, 0
};
static_assert(sizeof(SoftShadowUniforms) == 32);

// The struct's members as the shaders' blocks flatten them (softScales, softCounts), at `offset` in their block.
inline std::vector<rhi::UniformMember> softShadowMembers(std::uint32_t offset)
{
    return {{"softScales", offset + std::uint32_t(offsetof(SoftShadowUniforms, scales)), 16},
            {"softCounts", offset + std::uint32_t(offsetof(SoftShadowUniforms, counts)), 16}};
}

SoftShadowUniforms softShadowUniforms(const SoftShadowSettings& soft);

// tan of half a directional light's angular diameter (degrees).
float tanHalfAngularDiameter(float degrees);

} // namespace penumbra::shadows
