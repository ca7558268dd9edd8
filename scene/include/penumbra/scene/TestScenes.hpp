#pragma once

#include "penumbra/scene/Scene.hpp"

namespace penumbra::scene {

// The design document's shadow test scene (after the seeds' "plane with some opaque
// objects, four directional lights 90 degrees apart"): a 60 x 60 ground plane at y = 0;
// cubes, spheres and cylinders standing on it (their lowest points exactly at y = 0, so
// peter-panning shows as a gap at the contact) and floating above it; a wall for
// slope-bias acne; an 80-unit beam that runs from in front of the camera to far behind it
// (casters outside the view that the shadow frustum must pancake); a Clip panel with
// checker holes, a Dither sphere and a pillar that does not receive shadows.
// Object transforms are rigid (rotation and translation only), so normals transform with
// the transform's upper 3x3. Objects are found by name with Scene::findObject.
// Four lights, all 50 degrees below the horizon, yaw 30, 120, 210 and 300 degrees.
Scene makeShadowTestScene();

// The same geometry, materials and camera with only the first ("key") light.
Scene makeSingleLightScene();

} // namespace penumbra::scene
