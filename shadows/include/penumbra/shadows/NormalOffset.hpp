#pragma once

#include <glm/vec3.hpp>

namespace penumbra::shadows {

// The receiver's normal offset (Castano 2013, "Shadow Mapping Summary - Part 1"), the lit shader's
// receiverNormalOffset (shaders/shadow_filter.glsl): along the geometric normal turned towards the light, by
// reach * sin(theta), theta the angle between that normal and `towardsLight` (unit). A plane at angle theta rises
// reach * tan(theta) in light depth across a lookup that reaches `reach` world units around the receiver; moved d
// along its normal the receiver is d / cos(theta) in front of the plane, so d = reach * sin(theta) clears it.
glm::vec3 receiverNormalOffset(glm::vec3 geometricNormal, glm::vec3 towardsLight, float reach);

} // namespace penumbra::shadows
