#pragma once

#include "penumbra/scene/Scene.hpp"

namespace penumbra::scenes {

// The shadow test scene, one place for every shadow artefact to show: a 60 x 60 ground plane at y = 0;
// cubes, spheres and cylinders standing on it (their lowest points exactly at y = 0, so
// peter-panning shows as a gap at the contact) and floating above it; a wall for
// slope-bias acne; an 80-unit beam that runs from in front of the camera to far behind it
// (casters outside the view that the shadow frustum must pancake); a Clip panel with
// checker holes, a Dither sphere and a pillar that does not receive shadows.
// Object transforms are rigid (rotation and translation only), so normals transform with
// the transform's upper 3x3. Objects are found by name with Scene::findObject.
// Four lights, all 50 degrees below the horizon, yaw 30, 120, 210 and 300 degrees.
scene::Scene makeShadowTestScene();

// The same geometry, materials and camera with only the first ("key") light.
scene::Scene makeSingleLightScene();

// The same geometry and camera lit by the key light at half intensity, three spot lights aimed at
// objects and two point lights among them: 3 + 2 x 6 = 15 tiles of the local atlas.
scene::Scene makeMixedLightsScene();

// A closed 10 x 4 x 10 room (floor, ceiling and walls are boxes 0.2 thick, outside the interior
// x, z in [-5, 5], y in [0, 4]) with a pillar, a floating cube and a crate, lit by the point light
// "inside" at (0.5, 2, 0.3); the point light "outside" sits 0.4 behind the +z wall, shining at it.
// The camera stands inside near the -z wall looking at the +z wall.
scene::Scene makePointLightRoomScene();

// A forest for real-content shadows and benchmarks: an 80 x 80 heightfield terrain (2 450 triangles), five trees
// of about 5 000 triangles each (an opaque trunk and branches, alpha-tested leaf cards cut out by a leaf texture
// generated here), a camera standing among them at eye height (made for 16:9, 1280 x 720) and one sun, 40 degrees
// up. Objects: "terrain", "tree N wood" and "tree N leaves" for N = 1..5.
scene::Scene makeForestScene();

// Contact points for soft shadows, seen from straight above: a 20 x 20 ground (top at y = 0), a pole 3 high and
// 0.2 wide standing on it at the origin, a floating slab 1 above the ground at (1.2, -2.2) and a fence of eight
// thin slats at z = 2.2. One sun 45 degrees up shining towards +x with a 10 degree angular diameter, so the pole's
// shadow runs along +x from its foot (its point at height h falls at x = h) and widens with x. The camera looks down
// on x in about [-2, 5] with +x to the right and +z down the picture. Objects: "ground", "pole", "slab",
// "fence 1".."fence 8".
inline constexpr float kContactPoleHeight = 3.0f;
inline constexpr float kContactPoleHalfWidth = 0.1f;
scene::Scene makeContactScene();
// The contact scene lit by a spot light and a point light instead of its sun, seen low from where their shadows of
// the pole and the fence fall (for contact shadows towards local lights): the spot "spot" at (-2.5, 3, 0.5) shining
// down past the pole's -x side, the point light "point" low at (-3, 1.5, -2); the camera at (4, 2, -1) looks at
// (0, 0, 1).
scene::Scene makeContactLocalLightsScene();

// A town larger than the default shadow distance, for static and baked shadows: a 200 x 200 ground (top at y = 0)
// with 8 x 8 static buildings 6 to 22 high and 8 to 10 wide, 25 apart, and one dynamic red ball of radius 1 ("ball", at
// kTownBallStart) that applications move. One low sun; the camera looks over the town from above its south edge, so
// the distant buildings lie far beyond 100 units. Objects: "ground", "building 1".."building 64", "ball".
inline constexpr float kTownHalfSize = 100.0f;
inline constexpr glm::vec3 kTownBallStart{0.0f, 1.0f, 75.0f};
scene::Scene makeTownScene();

// Many objects of one mesh, for instanced drawing: `count` unit cubes ("cube 1".."cube <count>", one mesh and one
// material) standing on a ground ("ground") in a square grid, kCubeGridPitch apart, filled row by row; one sun; the
// camera low over the grid's edge looking across it.
inline constexpr float kCubeGridPitch = 3.0f;
scene::Scene makeCubeGridScene(std::uint32_t count);

// A street at night for many lights: 384 m of street along z (x in [-6, 6] road, pavements to |x| = 12) between
// two rows of 20 buildings; 48 trees and 128 lamp posts on the pavements, 40 parked cars. Local lights (kStreetLamps
// spot lights pointing straight down, then kStreetShopWindows point lights in front of the shop fronts) are ordered
// from the camera's end of the street outwards, so the first N of them (keepFirstLocalLights) light the nearest part.
// One dim moon. Geometry is simple boxes, cylinders and spheres, one mesh per shape scaled per object, so objects of a
// shape share a mesh and a material (instanced draws). Objects: "ground", "pavement -x", "pavement +x",
// "building N" (1..40), "tree N/0" trunk and "tree N/1" crown (1..48), "post N" (1..128), "car N/0" body and
// "car N/1" cabin (1..40): `--dynamic "car N"` moves a whole car.
inline constexpr std::uint32_t kStreetLamps = 256;
inline constexpr std::uint32_t kStreetShopWindows = 64;
inline constexpr std::uint32_t kStreetCars = 40;
scene::Scene makeStreetScene();

// Traffic on the street: kStreetMovingCars of its cars (every fourth, cars 1, 5, ..., 37, spread over its length)
// drive away from the camera at kStreetCarSpeed in the lane beside their kerb (|x| = kStreetLaneX), each from where it
// was parked and round again from the far end. Places them `seconds` after the start and makes them dynamic. Throws
// scene::SceneError for a scene without the street's cars.
inline constexpr std::uint32_t kStreetMovingCars = 10;
inline constexpr float kStreetCarSpeed = 10.0f; // metres per second
inline constexpr float kStreetLaneX = 2.5f;
void driveStreetCars(scene::Scene& scene, float seconds);
// How far the cars have driven after `seconds`, the street's length wrapped: 0 <= d < 384 m.
float streetCarDistance(float seconds);

} // namespace penumbra::scenes
