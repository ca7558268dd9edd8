#pragma once

#include "penumbra/scene/Camera.hpp"
#include "penumbra/scene/Geometry.hpp"
#include "penumbra/scene/Light.hpp"

namespace penumbra::scene {

// Where the default sun stands seen from the camera: above it and over its left shoulder, the key light of
// three-point lighting (a product shot's key light, 45 degrees up and to one side of the camera), so the faces
// the camera sees are lit and the shadows fall away from it, beside the model.
inline constexpr float kDefaultSunElevationDegrees = 45.0f;
inline constexpr float kDefaultSunAzimuthDegrees = 30.0f; // towards the camera's left, from straight behind it

// The light a scene without lights gets: white, intensity 1, shining from kDefaultSunElevationDegrees above the
// horizon behind `camera`, turned kDefaultSunAzimuthDegrees to its left. A camera looking straight down takes its
// picture's up as its forward direction on the ground.
DirectionalLight defaultSun(const Camera& camera);

// The distance from which a sphere of `radius` fills 1 / 1.1 of the narrower field of view of a frame of `aspect`
// (width / height) and vertical field of view `fovY`.
float framingDistance(float radius, float fovY, float aspect);

// A camera looking at the bounds' centre from above and in front (+z, +x), at the distance where the bounding
// sphere of the box fills 1 / 1.1 of the narrower field of view: the vertical one for frames at least as wide as
// they are high (`aspect` = width / height >= 1), the horizontal one for taller frames. Near and far planes around
// the bounding sphere. Empty bounds are framed as a unit box at the origin.
Camera framingCamera(const Bounds& bounds, float fovY = 1.0471976f, float aspect = 1.0f);

} // namespace penumbra::scene
