#include "penumbra/shadows/ContactLights.hpp"

#include <algorithm>
#include <glm/geometric.hpp>
#include <tuple>

namespace penumbra::shadows {

std::vector<std::uint32_t> nearestContactLights(glm::vec3 camera, std::span<const ContactLightCandidate> candidates,
                                                std::uint32_t count)
{
    struct Ranked {
        float toReach;
        float toLight;
        std::uint32_t light;
        bool operator<(const Ranked& o) const
        {
            return std::tie(toReach, toLight, light) < std::tie(o.toReach, o.toLight, o.light);
        }
    };
    std::vector<Ranked> ranked;
    ranked.reserve(candidates.size());
    for (const ContactLightCandidate& c : candidates) {
        const float toLight = glm::distance(camera, c.position);
        ranked.push_back({std::max(toLight - c.range, 0.0f), toLight, c.light});
    }
    const std::size_t kept = std::min<std::size_t>(count, ranked.size());
    std::partial_sort(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(kept), ranked.end());
    std::vector<std::uint32_t> lights;
    lights.reserve(kept);
    for (std::size_t i = 0; i < kept; ++i)
        lights.push_back(ranked[i].light);
    return lights;
}

} // namespace penumbra::shadows
