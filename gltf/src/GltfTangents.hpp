#pragma once

#include "penumbra/scene/Geometry.hpp"

#include <cstdint>

namespace penumbra::gltf {

// Fills every vertex's tangent from the triangles' uv set `texCoord` (0 or 1), for primitives with a
// normal texture but no TANGENT. glTF 2.0 section 3.7.2.1 recommends MikkTSpace; Debian 12 packages
// no MikkTSpace library, so this is NOT MikkTSpace: each triangle's tangent and bitangent come from
// its uv derivatives, are summed (area-weighted, unnormalised) into its vertices, and each vertex's
// sum is Gram-Schmidt orthogonalised against its normal; w is the handedness of the summed
// bitangent. It differs from MikkTSpace where MikkTSpace splits vertices: at uv mirroring seams and
// where triangles sharing a vertex disagree in handedness (here they average), and it weights by
// area rather than by angle, so a baked normal map matches it only on smooth, unmirrored charts.
void computeTangents(scene::MeshData& mesh, std::uint32_t texCoord);

} // namespace penumbra::gltf
