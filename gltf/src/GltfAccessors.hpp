#pragma once

#include "GltfDocument.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace penumbra::gltf {

// Typed reads of accessors, checked against the glTF rules they rely on: the accessor, its
// buffer view and buffer exist, the type and component type suit the use, every element lies
// inside the buffer view and the view inside its buffer, floats are finite. `owner` says who
// reads (e.g. "mesh 2 ('Cube') primitive 0") and `semantic` what for ("POSITION", "indices");
// both appear in the GltfError a failed check throws. Sparse accessors are refused.

// VEC3 of FLOAT (POSITION, NORMAL).
std::vector<glm::vec3> readVec3(const Document& document, int accessor, std::string_view owner,
                                std::string_view semantic);

// VEC2 of FLOAT, or of normalized UNSIGNED_BYTE / UNSIGNED_SHORT (TEXCOORD_n).
std::vector<glm::vec2> readTexCoords(const Document& document, int accessor, std::string_view owner,
                                     std::string_view semantic);

// VEC4 of FLOAT (TANGENT).
std::vector<glm::vec4> readVec4(const Document& document, int accessor, std::string_view owner,
                                std::string_view semantic);

// VEC4 of FLOAT, or of normalized BYTE / SHORT (EXT_mesh_gpu_instancing's ROTATION quaternions, x y z w).
std::vector<glm::vec4> readRotations(const Document& document, int accessor, std::string_view owner,
                                     std::string_view semantic);

// VEC3 or VEC4 of FLOAT, or of normalized UNSIGNED_BYTE / UNSIGNED_SHORT (COLOR_n); VEC3 gets alpha 1.
std::vector<glm::vec4> readColors(const Document& document, int accessor, std::string_view owner,
                                  std::string_view semantic);

// SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT (indices).
std::vector<std::uint32_t> readIndices(const Document& document, int accessor, std::string_view owner);

// Elements of `type` (TINYGLTF_TYPE_*) and one of `componentTypes`, their components one after another as floats:
// components of a normalized accessor mapped as glTF 2.0 section 3.11 says, other integers as they are (JOINTS_n).
std::vector<float> readComponents(const Document& document, int accessor, std::string_view owner,
                                  std::string_view semantic, int type, std::span<const int> componentTypes);

// The element count an accessor declares, after checking that it exists.
std::size_t accessorCount(const Document& document, int accessor, std::string_view owner);

} // namespace penumbra::gltf
