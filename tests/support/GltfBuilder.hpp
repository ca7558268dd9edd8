#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace penumbra::testing {

// The bytes of `values`, as a glTF buffer holds them.
template <typename T>
std::span<const std::uint8_t> bytesOf(std::span<const T> values)
{
    return {reinterpret_cast<const std::uint8_t*>(values.data()), values.size_bytes()};
}

// glTF component types, as the specification numbers them.
enum class Component : int {
    Byte = 5120,
    UnsignedByte = 5121,
    Short = 5122,
    UnsignedShort = 5123,
    UnsignedInt = 5125,
    Float = 5126
};

// Writes small glTF 2.0 files for tests: a JSON document plus one binary buffer that accessors,
// and images embedded in it, are appended to. Everything is public JSON to edit, so a test can
// break a file in exactly one place.
class GltfBuilder {
public:
    GltfBuilder();

    nlohmann::json& json() { return json_; }
    std::vector<std::uint8_t>& bin() { return bin_; }

    // Appends the bytes (4-byte aligned) as a buffer view and an accessor over it; returns the accessor.
    int addAccessor(std::span<const std::uint8_t> bytes, std::size_t count, const std::string& type,
                    Component component, bool normalized = false);
    int addPositions(std::span<const glm::vec3> values);
    int addNormals(std::span<const glm::vec3> values);
    int addUvs(std::span<const glm::vec2> values);
    // Indices stored with the given component type (UnsignedByte, UnsignedShort or UnsignedInt).
    int addIndices(std::span<const std::uint32_t> values, Component component);
    // A PNG of width x height RGBA8 texels as a buffer view image; returns the image index.
    int addPngImage(std::uint32_t width, std::uint32_t height, std::span<const std::uint8_t> rgba);

    // Appends to the named top-level array; returns the new element's index.
    int add(const std::string& array, nlohmann::json element);
    // Adds a node to the default scene's roots.
    void addRoot(int node);
    // Lists the extension in extensionsUsed, and in extensionsRequired when `required`, once each.
    void useExtension(const std::string& name, bool required = false);

    // .gltf with the buffer inline as a base64 data URI, or beside it as <stem>.bin.
    void writeGltf(const std::filesystem::path& path, bool externalBuffer = false) const;
    void writeGlb(const std::filesystem::path& path) const;
    // The whole document as writeGltf writes it, the buffer inline as a base64 data URI.
    nlohmann::json embedded() const;
    std::vector<std::uint8_t> glbBytes() const;

private:
    int addView(std::span<const std::uint8_t> bytes);
    nlohmann::json withBuffer(const std::string& uri) const;

    nlohmann::json json_;
    std::vector<std::uint8_t> bin_;
};

// What each instance of an EXT_mesh_gpu_instancing node gets; an empty list leaves its attribute out.
struct InstanceAttributes {
    std::vector<glm::vec3> translations;
    std::vector<glm::vec4> rotations; // quaternions x, y, z, w
    std::vector<glm::vec3> scales;
    // FLOAT, or normalized Byte or Short (each component rounded to the nearest step).
    Component rotationComponent = Component::Float;
};

// Adds `node` (a JSON object with a mesh) with EXT_mesh_gpu_instancing attributes, the extension listed as used and
// required as the extension recommends; returns the node index.
int addInstancedNode(GltfBuilder& builder, nlohmann::json node, const InstanceAttributes& instances);

// A cube of half size 1 as one primitive: 24 vertices with flat normals and uvs, 36 indices of
// the given component type, counter-clockwise seen from outside. Returns the mesh index.
int addCubeMesh(GltfBuilder& builder, const std::string& name, int material,
                Component indices = Component::UnsignedShort);

// One cube per entry of `samplers` (node "cube <i>"), its material's base colour texture a 4 x 4 picture
// sampled by that glTF sampler (a JSON object), or by none for a null entry.
GltfBuilder sampledTexturesScene(const std::vector<nlohmann::json>& samplers);

// What a quad mesh carries besides POSITION, NORMAL and TEXCOORD_0.
struct QuadAttributes {
    std::optional<glm::vec4> color; // COLOR_0 of every vertex, stored as normalized UNSIGNED_BYTE VEC3
                                    // when alpha is 1, FLOAT VEC4 otherwise
    std::optional<glm::vec4> tangent; // TANGENT of every vertex
    bool mirroredUv1 = false; // TEXCOORD_1 = (1 - u, v) of TEXCOORD_0
};

// A 2 x 2 quad in the xy plane facing +z (counter-clockwise seen from +z), u along +x and v along -y (uv (0, 0) at
// the top left corner, (-1, 1, 0)). Returns the mesh index.
int addQuadMesh(GltfBuilder& builder, const std::string& name, int material, const QuadAttributes& attributes = {});

// An RGBA8 picture of width x 1 texels, each given as one RGBA value, as an image and a texture; returns the texture.
int addTextureRow(GltfBuilder& builder, std::span<const std::array<std::uint8_t, 4>> texels);

// The scene the command-line tests render: a ground plane, a cube standing on it and a rotated,
// scaled one above it, a masked and a blended material, a directional light, a spot light, a
// point light and a camera named "overview" looking at the cubes.
GltfBuilder exampleScene();

// Every material feature the loader supports in one scene, for parity across configurations: a ground, a
// double-sided quad seen from behind, vertex colours, a metallic-roughness texture, a normal texture with and
// without tangents, occlusion and emissive textures, transformed and TEXCOORD_1 textures, an unlit quad and two
// blended ones; a sun and a camera named "materials".
GltfBuilder materialsScene();

// A UV sphere of radius 1 as one primitive (`segments` around, `rings` from pole to pole) with smooth normals and
// uvs, counter-clockwise seen from outside. Returns the mesh index.
int addSphereMesh(GltfBuilder& builder, const std::string& name, int material, int segments = 32, int rings = 16);

// Rows of spheres on a ground slab, no lights and no camera (the loader's defaults light and frame it): gold,
// silver and copper metals (metallic 1) and a white dielectric, roughness 0.1 to 0.9 along each row. The scene the
// default lighting is judged on: metals show what the lighting reflects.
GltfBuilder metallicSpheresScene();

// A cube whose base colour texture names an image file that does not exist ("textures/albedo.png", beside the
// .gltf), no lights and no camera.
GltfBuilder missingImageScene();

// The builder's document with its buffer inline as a base64 data URI, cut `keep` of the way into that URI, as a
// download that stopped early leaves it.
std::string truncatedGltf(const GltfBuilder& builder, double keep = 0.5);

// `count` cubes in a row, each with its own base colour and normal textures: PNGs of `side` x `side` texels of
// patterned noise (hard to compress, like photographed textures). For measuring how long images take to load.
GltfBuilder largeTexturesScene(int count, std::uint32_t side);

} // namespace penumbra::testing
