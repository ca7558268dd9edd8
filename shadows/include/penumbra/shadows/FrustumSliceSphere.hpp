#pragma once

#include "penumbra/shadows/ShadowCamera.hpp"
#include "penumbra/shadows/Sphere.hpp"

#include <array>
#include <glm/vec3.hpp>

namespace penumbra::shadows {

// The 8 world-space corners of the camera frustum between view depths nearDistance and farDistance.
std::array<glm::vec3, 8> frustumSliceCorners(const ShadowCamera& camera, float nearDistance, float farDistance);

// The smallest sphere holding the slice's corners. It sits on the view axis, so its radius depends
// on the slice alone (field of view, aspect, depths), never on the camera's position or rotation.
Sphere frustumSliceSphere(const ShadowCamera& camera, float nearDistance, float farDistance);

} // namespace penumbra::shadows
