#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace penumbra::scene {

// Coordinate system of every mesh and scene: right-handed, y up, metres.
// Front faces are counter-clockwise seen from outside, normals point outward; with the
// RHI's conventions (CCW front faces in NDC, y up) back-face culling keeps the outside.

// The vertex layout the lit pass and the shadow caster pass read: six attributes, tightly packed
// (offsets 0, 12, 24, 32, 40 and 56, stride 72).
struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 uv{0.0f}; // TEXCOORD_0; v = 0 is the top row of a texture, as in the RHI
    glm::vec2 uv1{0.0f}; // TEXCOORD_1
    // xyz along +u of the normal texture's uv set, w = +1 or -1: bitangent = w * cross(normal, xyz)
    // (glTF 2.0 section 3.7.2.1, TANGENT). Only read for materials with a normal texture.
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};
    glm::vec4 color{1.0f}; // COLOR_0, linear, multiplies the base colour
};
static_assert(sizeof(Vertex) == 72, "Vertex must stay tightly packed: vertex input strides depend on it");

// Axis-aligned box. The default value is empty (min > max), so extend() from it gives the
// box of exactly the points added.
struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};

    // Whether nothing was added yet.
    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    // The middle of the box.
    glm::vec3 center() const { return 0.5f * (min + max); }
    // Extent along each axis.
    glm::vec3 size() const { return max - min; }

    // Grows the box to hold `point`.
    void extend(const glm::vec3& point);
    // Grows the box to hold `other`.
    void extend(const Bounds& other);
    // The smallest box holding both.
    Bounds merged(const Bounds& other) const;
    // Whether `point` lies in the box grown by `tolerance` on every side.
    bool contains(const glm::vec3& point, float tolerance = 0.0f) const;

    // Corner i has x from max when bit 0 of i is set, y from bit 1, z from bit 2.
    std::array<glm::vec3, 8> corners() const;
    // The world box of the 8 transformed corners: conservative for any affine transform.
    Bounds transformed(const glm::mat4& transform) const;
};

// Indexed triangle list; `bounds` is the box of the vertex positions.
struct MeshData {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    Bounds bounds;

    // Triangles of the mesh (indices / 3).
    std::uint32_t triangleCount() const { return static_cast<std::uint32_t>(indices.size() / 3); }
};

// Recomputes mesh.bounds from its vertices.
void updateBounds(MeshData& mesh);

} // namespace penumbra::scene
