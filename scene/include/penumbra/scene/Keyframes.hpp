#pragma once

#include "penumbra/scene/Rig.hpp"

#include <glm/gtc/quaternion.hpp>

#include <vector>

namespace penumbra::scene {

// Keyframe sampling as glTF 2.0 Appendix C ("Animation Sampler Interpolation Modes") defines it. Before the first
// key the value is the first key's, after the last the last key's (section 3.11: clamped, not extrapolated).

// The `keys.width` components at `time`: STEP holds the value of the key at or before `time`, LINEAR interpolates
// linearly, CUBICSPLINE evaluates the Hermite spline whose tangents are the stored ones times the key interval.
std::vector<float> sampleKeyframes(const Keyframes& keys, float time);

// A rotation channel at `time` (keys of x, y, z, w): LINEAR by slerp along the shorter arc, CUBICSPLINE's spline
// value normalized; always a unit quaternion.
glm::quat sampleRotation(const Keyframes& keys, float time);

// Appendix C's slerp: the shorter arc from a to b at u in [0, 1] (b negated when the dot product is negative),
// falling back to a normalized linear blend where the two are nearly equal and sin(angle) vanishes.
glm::quat slerpShorter(const glm::quat& a, const glm::quat& b, float u);

} // namespace penumbra::scene
