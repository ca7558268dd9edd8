#pragma once

#include "GltfDocument.hpp"

#include "penumbra/scene/Geometry.hpp"

namespace penumbra::scene::gltf {

// One TRIANGLES primitive as an indexed triangle list with bounds. Without NORMAL the triangles
// get flat normals (each its own three vertices), as glTF requires; without indices the vertices
// are taken three by three. Throws GltfError for any other mode, missing POSITION, attributes of
// other counts than POSITION, indices past POSITION's count or not a multiple of 3, or no vertices.
MeshData readPrimitive(const Document& document, int mesh, int primitive);

// The same triangles with the opposite winding, for objects whose transform mirrors.
MeshData reversedWinding(MeshData mesh);

} // namespace penumbra::scene::gltf
