#pragma once

#include "penumbra/scene/Geometry.hpp"

#include <cstdint>

namespace penumbra::scene {

// Procedural meshes centred on the origin, y up. All are outward-facing with
// counter-clockwise front faces seen from outside and carry no degenerate triangles
// (every triangle has a well-defined geometric normal).

// Axis-aligned box with separate vertices per face (flat normals); each face's uv spans
// [0, 1] with v = 0 at the face's upper edge (side faces), its -z edge (top face) or its
// +z edge (bottom face).
MeshData makeBox(const glm::vec3& halfExtents);

// UV sphere: `segments` slices around y (>= 3), `rings` bands from pole to pole (>= 2).
// u runs around y from +z towards +x, v from the north pole (0) to the south pole (1).
// The poles are closed with one triangle per segment, not degenerate quads.
MeshData makeSphere(float radius, std::uint32_t segments, std::uint32_t rings);

// Capped cylinder along y from -halfHeight to +halfHeight; the side has smooth normals,
// the caps flat ones (separate vertices on the rims). u runs around like makeSphere's.
MeshData makeCylinder(float radius, float halfHeight, std::uint32_t segments);

// Square in the xz plane at y = 0 facing +y, split into subdivisions x subdivisions
// quads (more vertices let a vertex-lit or displaced variant show detail; one is enough
// for a flat floor). uv spans [0, 1] over the plane, v = 0 at -z.
MeshData makePlane(float halfSize, std::uint32_t subdivisions = 1);

} // namespace penumbra::scene
