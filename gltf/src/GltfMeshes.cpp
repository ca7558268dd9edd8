#include "GltfMeshes.hpp"

#include "GltfAccessors.hpp"
#include "GltfLimits.hpp"
#include "GltfTangents.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <numeric>
#include <utility>

namespace penumbra::gltf {
namespace {

constexpr int kTriangles = TINYGLTF_MODE_TRIANGLES;

std::string modeName(int mode)
{
    switch (mode) {
    case TINYGLTF_MODE_POINTS:
        return "POINTS";
    case TINYGLTF_MODE_LINE:
        return "LINES";
    case TINYGLTF_MODE_LINE_LOOP:
        return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP:
        return "LINE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_STRIP:
        return "TRIANGLE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_FAN:
        return "TRIANGLE_FAN";
    }
    return fmt::format("{}", mode);
}

int primitiveAttribute(const tinygltf::Primitive& primitive, const std::string& name)
{
    const auto found = primitive.attributes.find(name);
    return found == primitive.attributes.end() ? -1 : found->second;
}

// Flat shading: every triangle gets its own vertices carrying its face normal. Degenerate
// triangles cover no pixel; they get +y so that no normal is NaN.
scene::MeshData flatShaded(const std::vector<scene::Vertex>& vertices, const std::vector<std::uint32_t>& indices)
{
    scene::MeshData mesh;
    mesh.vertices.reserve(indices.size());
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        scene::Vertex a = vertices[indices[t]], b = vertices[indices[t + 1]], c = vertices[indices[t + 2]];
        const glm::vec3 cross = glm::cross(b.position - a.position, c.position - a.position);
        const float length = glm::length(cross);
        const glm::vec3 normal = length > 0.0f ? cross / length : glm::vec3(0.0f, 1.0f, 0.0f);
        a.normal = b.normal = c.normal = normal;
        mesh.vertices.insert(mesh.vertices.end(), {a, b, c});
    }
    mesh.indices.resize(mesh.vertices.size());
    std::iota(mesh.indices.begin(), mesh.indices.end(), 0u);
    return mesh;
}

} // namespace

scene::MeshData readPrimitive(const Document& document, int meshIndex, int primitiveIndex,
                              std::optional<std::uint32_t> normalTexCoord)
{
    const tinygltf::Mesh& gltfMesh = document.model().meshes[std::size_t(meshIndex)];
    const tinygltf::Primitive& primitive = gltfMesh.primitives[std::size_t(primitiveIndex)];
    const std::string owner =
        fmt::format("{} primitive {}", describe("mesh", meshIndex, gltfMesh.name), primitiveIndex);
    if (primitive.mode != -1 && primitive.mode != kTriangles)
        document.fail(fmt::format("{}: mode {} is not supported, only TRIANGLES", owner, modeName(primitive.mode)));
    const int positionAccessor = primitiveAttribute(primitive, "POSITION");
    if (positionAccessor < 0)
        document.fail(fmt::format("{}: has no POSITION attribute", owner));

    const std::vector<glm::vec3> positions = readVec3(document, positionAccessor, owner, "POSITION");
    if (positions.empty())
        document.fail(fmt::format("{}: accessor {} (POSITION) has no vertices", owner, positionAccessor));
    for (std::size_t i = 0; i < positions.size(); ++i)
        if (glm::any(glm::greaterThan(glm::abs(positions[i]), glm::vec3(kMaxCoordinate))))
            document.fail(
                fmt::format("{}: accessor {} (POSITION) element {} is ({:g}, {:g}, {:g}), over the limit of {:g} "
                            "for a coordinate",
                            owner, positionAccessor, i, positions[i].x, positions[i].y, positions[i].z,
                            kMaxCoordinate));
    std::vector<scene::Vertex> vertices(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i)
        vertices[i].position = positions[i];

    const auto checkCount = [&](int accessor, const std::string& semantic, std::size_t count) {
        if (count != positions.size())
            document.fail(fmt::format("{}: accessor {} ({}) has {} elements but POSITION has {}", owner, accessor,
                                      semantic, count, positions.size()));
    };
    // Reads the attribute `semantic`, if the primitive has it, into each vertex with `store`.
    const auto readAttribute = [&](const std::string& semantic, auto read, auto store) {
        const int accessor = primitiveAttribute(primitive, semantic);
        if (accessor < 0)
            return false;
        const auto values = read(document, accessor, owner, semantic);
        checkCount(accessor, semantic, values.size());
        for (std::size_t i = 0; i < values.size(); ++i)
            store(vertices[i], values[i]);
        return true;
    };
    const bool hasNormals =
        readAttribute("NORMAL", readVec3, [](scene::Vertex& v, const glm::vec3& n) { v.normal = n; });
    readAttribute("TEXCOORD_0", readTexCoords, [](scene::Vertex& v, const glm::vec2& uv) { v.uv = uv; });
    readAttribute("TEXCOORD_1", readTexCoords, [](scene::Vertex& v, const glm::vec2& uv) { v.uv1 = uv; });
    readAttribute("COLOR_0", readColors, [](scene::Vertex& v, const glm::vec4& c) { v.color = c; });
    // glTF 2.0 section 3.7.2.1: TANGENT is only used together with NORMAL; flat normals need their own.
    const bool hasTangents =
        hasNormals && readAttribute("TANGENT", readVec4, [](scene::Vertex& v, const glm::vec4& t) { v.tangent = t; });

    std::vector<std::uint32_t> indices;
    if (primitive.indices >= 0) {
        indices = readIndices(document, primitive.indices, owner);
        for (const std::uint32_t index : indices)
            if (index >= positions.size())
                document.fail(fmt::format("{}: accessor {} (indices) refers to vertex {} but POSITION has {}", owner,
                                          primitive.indices, index, positions.size()));
    } else {
        indices.resize(positions.size());
        std::iota(indices.begin(), indices.end(), 0u);
    }
    if (indices.empty() || indices.size() % 3 != 0)
        document.fail(fmt::format("{}: {} {} do not make whole triangles", owner, indices.size(),
                                  primitive.indices >= 0 ? "indices" : "vertices"));

    scene::MeshData mesh;
    if (hasNormals) {
        mesh.vertices = std::move(vertices);
        mesh.indices = std::move(indices);
    } else {
        mesh = flatShaded(vertices, indices);
    }
    if (normalTexCoord && !hasTangents)
        computeTangents(mesh, *normalTexCoord);
    updateBounds(mesh);
    return mesh;
}

scene::MeshData reversedWinding(scene::MeshData mesh)
{
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    return mesh;
}

} // namespace penumbra::gltf
