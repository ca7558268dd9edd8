#include "GltfDeviations.hpp"

#include <fmt/format.h>

namespace penumbra::gltf {

void Deviations::add(std::string_view kind, const std::string& pointer)
{
    auto found = kinds_.find(kind);
    if (found == kinds_.end())
        found = kinds_.emplace(std::string(kind), std::pair{pointer, std::size_t(0)}).first;
    ++found->second.second;
}

std::vector<std::string> Deviations::notes() const
{
    std::vector<std::string> out;
    for (const auto& [kind, where] : kinds_)
        out.push_back(where.second > 1
                          ? fmt::format("tolerated: {} at {} (and {} more)", kind, where.first, where.second - 1)
                          : fmt::format("tolerated: {} at {}", kind, where.first));
    return out;
}

} // namespace penumbra::gltf
