#pragma once

#include "penumbra/scene/Camera.hpp"
#include "penumbra/scene/Geometry.hpp"
#include "penumbra/scene/Light.hpp"

namespace penumbra::scene {

// The light a scene without lights gets: white, intensity 1, 50 degrees below the horizon and
// turned 30 degrees, like the test scene's key light.
DirectionalLight defaultSun();

// A camera looking at the bounds' centre from above and in front (+z, +x), far enough that the
// bounding sphere fits the vertical field of view, with near and far planes around the sphere.
// Empty bounds are framed as a unit sphere at the origin.
Camera framingCamera(const Bounds& bounds, float fovY = 1.0471976f);

} // namespace penumbra::scene
