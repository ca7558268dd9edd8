#pragma once

#include "penumbra/scene/Camera.hpp"
#include "penumbra/scene/Geometry.hpp"
#include "penumbra/scene/Light.hpp"

namespace penumbra::scene {

// The light a scene without lights gets: white, intensity 1, 50 degrees below the horizon and
// turned 30 degrees, like the test scene's key light.
DirectionalLight defaultSun();

// A camera looking at the bounds' centre from above and in front (+z, +x), at the distance where the
// box's corners fill 1 / 1.1 of the vertical field of view in their larger direction (across or up),
// so the bounds fill most of any frame at least as wide as it is high; near and far planes around the
// bounding sphere.
// Empty bounds are framed as a unit sphere at the origin.
Camera framingCamera(const Bounds& bounds, float fovY = 1.0471976f);

} // namespace penumbra::scene
