#pragma once

#include "GltfFields.hpp"

#include <limits>
#include <map>
#include <string>
#include <vector>

namespace penumbra::gltf {

// The glTF component types (glTF 2.0, section 5.1.3, accessor.componentType).
inline constexpr std::int64_t kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123,
                              kUnsignedInt = 5125, kFloat = 5126;
// The largest integer a schema check accepts where the specification sets no maximum.
inline constexpr std::int64_t kMaxInteger = std::numeric_limits<std::int64_t>::max();

std::int64_t componentSize(std::int64_t componentType);
// How many components an accessor type ("SCALAR", "VEC3", "MAT4"...) has.
std::size_t componentCount(const std::string& type);

// Checks a glTF file's JSON as the Khronos glTF Validator does before any data is read: the type,
// range and enum values of every property the loader reads, required properties, every index, the
// node hierarchy (no loops, one parent, scenes list roots), the accessor formats each mesh attribute
// allows, and texture coordinate sets that materials refer to. Throws GltfError naming the JSON
// pointer of the first offending value.
void checkSchema(const JsonFile& file);

// The JSON of accessor `index` (an index the schema has checked).
const Json& accessorJson(const JsonFile& file, int index);

// What each accessor is used as ("vertex attribute", "indices", "instance attribute"): one accessor serves one use.
using AccessorUsage = std::map<int, std::string>;

// The parts of checkSchema by topic.
void checkMaterials(const JsonFile& file);
void checkTexturesAndImages(const JsonFile& file);
void checkCamerasAndLights(const JsonFile& file);
// Skins, animations and morph target counts: required properties, indices, enums, accessor formats.
void checkSkinsAndAnimations(const JsonFile& file);
// The node's EXT_mesh_gpu_instancing object, when it has one: a node with a mesh, at least one attribute, each
// an accessor of the format the extension allows that nothing else uses, all of one count. Returns that count,
// the node's instances (0 without the extension).
std::uint64_t checkInstancing(const JsonFile& file, const Fields& node, AccessorUsage& usage);

// The top-level array `name` as objects (none when absent).
std::vector<Fields> topLevel(const JsonFile& file, std::string_view name);

} // namespace penumbra::gltf
