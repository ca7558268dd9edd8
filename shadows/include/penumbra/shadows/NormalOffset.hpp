#pragma once

#include "penumbra/shadows/ShadowSettings.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>

namespace penumbra::shadows {

// What the caster pass needs to move a view's casters: the lookup reach (world units; per unit of distance from the
// light for positional lights) and the light's direction into the scene (w = 0) or position (w = 1). A reach of 0
// draws casters where they are.
struct CasterNormalOffset {
    float reach = 0.0f;
    glm::vec4 light{0.0f};
};

// The receiver's normal offset (Castano 2013, "Shadow Mapping Summary - Part 1"), the lit shader's
// receiverNormalOffset (shaders/shadow_filter.glsl): along the geometric normal turned towards the light, by
// reach * sin(theta), theta the angle between that normal and `towardsLight` (unit). A plane at angle theta rises
// reach * tan(theta) in light depth across a lookup that reaches `reach` world units around the receiver; moved d
// along its normal the receiver is d / cos(theta) in front of the plane, so d = reach * sin(theta) clears it.
glm::vec3 receiverNormalOffset(glm::vec3 geometricNormal, glm::vec3 towardsLight, float reach);

// The normal offset's reach (world units) for a map of `texelSize` and `filter`: normalBias filter-sized texel
// diagonals (the filter's reach k texels times sqrt 2, the worst case across a texel).
float normalOffsetReach(float normalBias, float texelSize, ShadowFilter filter);

} // namespace penumbra::shadows
