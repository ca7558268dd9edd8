#pragma once

#include <cstdint>

namespace penumbra::gltf {

// What a glTF file may ask for, refused with a named error before anything is allocated for it (the
// limits of pictures are in GltfImages.hpp). Far above what a scene rendered here needs; they keep a
// hostile or broken file from exhausting memory or the stack.
inline constexpr std::uint64_t kMaxFileBytes = std::uint64_t(1) << 30; // a .gltf, .glb or .bin file
inline constexpr std::uint64_t kMaxBufferBytes = std::uint64_t(1) << 30; // buffer.byteLength
inline constexpr std::uint64_t kMaxAccessorElements = std::uint64_t(1) << 24; // accessor.count
inline constexpr std::uint64_t kMaxObjects = 100000; // elements of each top-level array (nodes, meshes...)
inline constexpr std::uint64_t kMaxNodeDepth = 1000; // nodes from a root to its deepest descendant
// EXT_mesh_gpu_instancing instances of all nodes together: each becomes a scene object of its own, so they are
// bounded like the nodes that would otherwise carry them.
inline constexpr std::uint64_t kMaxInstances = kMaxObjects;
inline constexpr int kMaxJsonDepth = 128; // nested JSON objects and arrays
// The largest position coordinate, in an accessor and in world space: squares and products of two (lengths, matrix
// products, the bounds' diagonal) stay finite in float (3.4e38) with room to spare, and a valid file whose bytes
// make some vertices enormous is refused by accessor and element instead of failing inside the renderer.
inline constexpr float kMaxCoordinate = 1e16f;

} // namespace penumbra::gltf
