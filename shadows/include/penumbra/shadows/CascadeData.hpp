#pragma once

#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shadows/FrustumSliceSphere.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <array>
#include <cstddef>
#include <glm/vec3.hpp>

namespace penumbra::shadows {

// What the lit shader needs per cascade (the document's SetCascadeData), the GLSL struct CascadeData of the block
// DirectionalShadows (DirectionalShadowUniforms::cascades).
struct alignas(16) CascadeData {
    // The culling sphere shrunk by the filter size, r' = r - texelSize * filterFactor, so that the filter taps of a
    // selected receiver stay inside the tile: its centre and r'^2 (the stable fit's selection).
    glm::vec3 selectionCentre{0.0f};
    float selectionRadiusSquared = 0.0f;
    float fadeScale = 0.0f; // 1 / r'^2: the stable fit's cascade fade scale on squared distance
    // texelSize * filterFactor * sqrt 2: the normal bias in world units per unit bias (sqrt 2: a texel's diagonal is
    // the worst case).
    float normalBias = 0.0f;
    float texelWorldSize = 0.0f; // a texel's world size (soft shadows' penumbrae in world units)
    float farDepth = 0.0f; // the view depth where the cascade ends (the close fit's selection and fade)
};

inline constexpr std::array kCascadeDataFields{
    PENUMBRA_SHADER_FIELD(CascadeData, selectionCentre), PENUMBRA_SHADER_FIELD(CascadeData, selectionRadiusSquared),
    PENUMBRA_SHADER_FIELD(CascadeData, fadeScale),       PENUMBRA_SHADER_FIELD(CascadeData, normalBias),
    PENUMBRA_SHADER_FIELD(CascadeData, texelWorldSize),  PENUMBRA_SHADER_FIELD(CascadeData, farDepth),
};
inline constexpr shaders::ShaderStruct kCascadeDataStruct{"CascadeData", sizeof(CascadeData), kCascadeDataFields};
static_assert(shaders::matchesLayout(kCascadeDataStruct, shaders::BlockLayout::Std140, true));

CascadeData cascadeData(const Sphere& cullingSphere, float texelSize, ShadowFilter filter, float farDepth);

} // namespace penumbra::shadows
