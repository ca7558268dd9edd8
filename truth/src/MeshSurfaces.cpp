#include "MeshSurfaces.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <map>
#include <numeric>

namespace penumbra::truth {
namespace {

// Union-find over vertices with path halving (Tarjan and van Leeuwen, "Worst-case Analysis of Set Union
// Algorithms", 1984).
std::uint32_t root(std::vector<std::uint32_t>& parent, std::uint32_t v)
{
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

void join(std::vector<std::uint32_t>& parent, std::uint32_t a, std::uint32_t b)
{
    a = root(parent, a);
    b = root(parent, b);
    if (a != b)
        parent[std::max(a, b)] = std::min(a, b);
}

} // namespace

std::vector<std::uint32_t> meshSurfaces(const scene::MeshData& mesh)
{
    std::vector<std::uint32_t> parent(mesh.vertices.size());
    std::iota(parent.begin(), parent.end(), 0u);
    std::map<std::array<std::uint32_t, 3>, std::uint32_t> firstAt;
    for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v) {
        const glm::vec3 p = mesh.vertices[v].position;
        const auto [it, inserted] =
            firstAt.try_emplace({std::bit_cast<std::uint32_t>(p.x), std::bit_cast<std::uint32_t>(p.y),
                                 std::bit_cast<std::uint32_t>(p.z)},
                                v);
        if (!inserted)
            join(parent, it->second, v);
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        join(parent, mesh.indices[t], mesh.indices[t + 1]);
        join(parent, mesh.indices[t], mesh.indices[t + 2]);
    }
    std::vector<std::uint32_t> surfaces(mesh.triangleCount());
    for (std::uint32_t t = 0; t < surfaces.size(); ++t)
        surfaces[t] = root(parent, mesh.indices[3 * std::size_t(t)]);
    return surfaces;
}

} // namespace penumbra::truth
