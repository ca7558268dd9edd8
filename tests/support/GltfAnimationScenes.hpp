#pragma once

#include "GltfBuilder.hpp"

#include <glm/vec3.hpp>

#include <span>
#include <string>

namespace penumbra::testing {

// Hand-built animated glTF files for the animation tests, values chosen so that the pose at a known time can be
// computed by hand from glTF 2.0's formulas.

// How the bend scene stores its skin weights.
enum class BendWeights {
    Float, // FLOAT, each vertex's weights summing to 1
    UnsignedByte, // normalized UNSIGNED_BYTE, summing to 255
    Unnormalized, // normalized UNSIGNED_BYTE summing to 200 / 255, not 1 (what an exporter may write)
};

// A two-bone bend: a square bar 0.2 wide from y = 0 to y = 2 (rings of 4 vertices at y = 0, 1 and 2: vertices 0-3,
// 4-7, 8-11), skinned to joint 0 "root" at the origin and joint 1 "elbow" at (0, 1, 0) (inverse bind matrices the
// identity and a translation by (0, -1, 0)); ring 0 follows the root, ring 2 the elbow, ring 1 both by half. Its
// animation 0, "bend", turns the elbow about +z, LINEAR from no turn at t = 0 to 90 degrees at t = 1; animation 1,
// "lift", moves the root up by 1 at t = 0.5 (STEP). A ground, a sun from above and a camera "side" looking at the bar
// along -z. Vertex 8 is (0.1, 2, 0.1): at t = 1 of "bend" it is at (-1, 1.1, 0.1), at t = 0.5 at
// (0.1 cos 45 - sin 45, 1 + 0.1 sin 45 + cos 45, 0.1).
GltfBuilder twoBoneBendScene(BendWeights weights = BendWeights::Float);

// A quad (addQuadMesh's, vertex 0 at (-1, 1, 0)) with two morph targets: target 0 moves vertex 0 by (0, 0, 1),
// target 1 every vertex by (0, 1, 0); mesh weights (0.5, 0). Animation "morph" drives the weights LINEAR from
// (0, 0) at t = 0 to (1, 0.5) at t = 2.
GltfBuilder morphScene();

// Two cubes under the nodes "step" and "spline". "step" is translated along x by a STEP channel with keys at
// t = 0, 1, 2 of x = 0, 5, 10. "spline" by a CUBICSPLINE channel with keys at t = 0 and 2: key 0 value 0 and
// out-tangent (1, 0, 0), key 1 in-tangent (3, 0, 0) and value (4, 0, 0) (its other tangents 0).
GltfBuilder keyframeScene();

// A walking figure of boxes (about 1.75 tall, facing +z, feet on the ground at y = 0) as ONE skinned mesh with
// vertex colours: pelvis, torso, head, upper and lower arms, thighs, shins and feet over the joints "hips", "spine",
// "head", "shoulder.L/R", "elbow.L/R", "leg.L/R" and "knee.L/R" (left is +x), weights blended over 8 cm either side
// of a joint. Animation "walk" loops every second: LINEAR rotations sampled 16 times, the legs swinging 25 degrees
// and the arms 20 degrees in opposition, the swinging knee bent, the hips turning and dropping so that the straight
// leg reaches the ground. A ground 8 x 8, a sun "sun" low from the left, a spot light "spot" from the front and a
// camera "front" looking at the figure and its shadows.
GltfBuilder walkingCharacterScene();

// Appends an accessor of FLOAT components of `type` (SCALAR, VEC3, VEC4, MAT4) with min and max; returns it.
int addFloatAccessor(GltfBuilder& builder, std::span<const float> values, const std::string& type);

// Appends an animation sampler (glTF 2.0 section 5.5: `times` as its input, `values` of `type` as its output) to
// `samplers`; returns its index there.
int addSampler(GltfBuilder& builder, nlohmann::json& samplers, std::span<const float> times,
               std::span<const float> values, const std::string& type, const std::string& interpolation);

} // namespace penumbra::testing
