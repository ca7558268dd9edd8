#pragma once

#include "penumbra/scene/Geometry.hpp"

#include <cstdint>
#include <vector>

namespace penumbra::truth {

// The connected surfaces of a mesh: per triangle, the index of its piece, triangles joined where they share a vertex
// position (exactly, so that a cube whose faces keep their own vertices is one piece and a leaf card, whose
// corners touch no other card, is its own). A piece is named by its lowest vertex index.
std::vector<std::uint32_t> meshSurfaces(const scene::MeshData& mesh);

} // namespace penumbra::truth
