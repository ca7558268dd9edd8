#include "penumbra/scene/Skinning.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>

namespace penumbra::scene {
namespace {

glm::vec3 normalizedOr(const glm::vec3& v, const glm::vec3& fallback)
{
    const float length = glm::length(v);
    return length > 0.0f ? v / length : fallback;
}

// Each triangle's three vertices (the flat-shaded layout) get its face normal; degenerate ones +y, as the loader does.
void flatten(std::vector<Vertex>& vertices)
{
    for (std::size_t t = 0; t + 2 < vertices.size(); t += 3) {
        const glm::vec3 cross = glm::cross(vertices[t + 1].position - vertices[t].position,
                                           vertices[t + 2].position - vertices[t].position);
        const glm::vec3 normal = normalizedOr(cross, glm::vec3(0.0f, 1.0f, 0.0f));
        vertices[t].normal = vertices[t + 1].normal = vertices[t + 2].normal = normal;
    }
}

} // namespace

std::vector<glm::mat4> jointMatrices(const Skin& skin, std::span<const glm::mat4> world)
{
    std::vector<glm::mat4> out(skin.joints.size());
    for (std::size_t j = 0; j < skin.joints.size(); ++j)
        out[j] = world[skin.joints[j]] * skin.inverseBind[j];
    return out;
}

Vertex morphVertex(const Vertex& rest, std::span<const MorphTarget> targets, std::span<const float> weights,
                   std::size_t vertex)
{
    Vertex out = rest;
    for (std::size_t t = 0; t < targets.size() && t < weights.size(); ++t) {
        const float w = weights[t];
        if (w == 0.0f)
            continue;
        if (!targets[t].positions.empty())
            out.position += w * targets[t].positions[vertex];
        if (!targets[t].normals.empty())
            out.normal += w * targets[t].normals[vertex];
        if (!targets[t].tangents.empty())
            out.tangent += glm::vec4(w * targets[t].tangents[vertex], 0.0f);
    }
    return out;
}

glm::mat4 skinMatrix(std::span<const glm::uvec4> joints, std::span<const glm::vec4> weights,
                     std::span<const glm::mat4> jointMatrices)
{
    glm::mat4 sum(0.0f);
    for (std::size_t set = 0; set < joints.size(); ++set)
        for (int i = 0; i < 4; ++i)
            if (weights[set][i] != 0.0f)
                sum += weights[set][i] * jointMatrices[joints[set][i]];
    return sum;
}

Vertex skinVertex(const Vertex& vertex, const glm::mat4& skin)
{
    Vertex out = vertex;
    out.position = glm::vec3(skin * glm::vec4(vertex.position, 1.0f));
    const glm::mat3 linear(skin);
    out.normal = normalizedOr(glm::transpose(glm::inverse(linear)) * vertex.normal, vertex.normal);
    out.tangent =
        glm::vec4(normalizedOr(linear * glm::vec3(vertex.tangent), glm::vec3(vertex.tangent)), vertex.tangent.w);
    return out;
}

std::vector<Vertex> deformVertices(const Deformer& deformer, std::span<const float> weights,
                                   std::span<const glm::mat4> jointMatrices)
{
    std::vector<Vertex> out(deformer.rest.size());
    const std::size_t sets = deformer.influenceSets;
    for (std::size_t v = 0; v < out.size(); ++v) {
        Vertex vertex = morphVertex(deformer.rest[v], deformer.targets, weights, v);
        if (deformer.skin >= 0) {
            const glm::mat4 skin = skinMatrix(std::span(deformer.joints).subspan(v * sets, sets),
                                              std::span(deformer.weights).subspan(v * sets, sets), jointMatrices);
            vertex = skinVertex(vertex, skin);
        } else {
            const Vertex& rest = deformer.rest[v];
            vertex.normal = normalizedOr(vertex.normal, rest.normal);
            vertex.tangent =
                glm::vec4(normalizedOr(glm::vec3(vertex.tangent), glm::vec3(rest.tangent)), rest.tangent.w);
        }
        out[v] = vertex;
    }
    if (deformer.flatNormals)
        flatten(out);
    return out;
}

} // namespace penumbra::scene
