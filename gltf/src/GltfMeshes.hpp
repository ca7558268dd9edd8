#pragma once

#include "GltfDocument.hpp"

#include "penumbra/scene/Geometry.hpp"

#include <cstdint>
#include <optional>

namespace penumbra::gltf {

// One TRIANGLES primitive as an indexed triangle list with bounds. Without NORMAL the triangles
// get flat normals (each its own three vertices), as glTF requires; without indices the vertices
// are taken three by three. Throws GltfError for any other mode, missing POSITION, attributes of
// other counts than POSITION, indices past POSITION's count or not a multiple of 3, or no vertices.
// Also reads TEXCOORD_1, COLOR_0 (multiplying the base colour) and TANGENT; a primitive whose material
// has a normal texture read through uv set `normalTexCoord` and that has no TANGENT gets computed
// tangents (computeTangents).
scene::MeshData readPrimitive(const Document& document, int mesh, int primitive,
                              std::optional<std::uint32_t> normalTexCoord);

// The same triangles with the opposite winding, for objects whose transform mirrors.
scene::MeshData reversedWinding(scene::MeshData mesh);

} // namespace penumbra::gltf
