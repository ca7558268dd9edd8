#include "penumbra/shadows/LightSpaceCache.hpp"

#include <algorithm>
#include <limits>
#include <optional>

namespace penumbra::shadows {

const LightSpaceCasters& LightSpaceCache::casters(glm::vec3 direction, std::span<const Bounds> world,
                                                  const CasterChanges& changes)
{
    ++calls_;
    auto light = std::find_if(lights_.begin(), lights_.end(), [&](const Light& l) { return l.direction == direction; });
    std::optional<std::vector<CasterRange>> changed;
    if (light != lights_.end() && light->casters.light.size() == world.size())
        changed = changes.since(light->generation);
    if (light == lights_.end()) {
        if (lights_.size() < kKeptLights)
            light = lights_.emplace(lights_.end());
        else
            light = std::min_element(lights_.begin(), lights_.end(),
                                     [](const Light& a, const Light& b) { return a.used < b.used; });
        light->direction = direction;
    }
    if (!changed) {
        light->casters = lightSpaceCasters(lightBasis(direction), world);
    } else {
        LightSpaceCasters& casters = light->casters;
        casters.world = world;
        for (const CasterRange& range : *changed) {
            for (std::uint32_t i = range.first; i < range.first + range.count; ++i)
                casters.light[i] = lightSpaceBounds(casters.basis, world[i]);
            refitChunks(casters, range.first, range.first + range.count);
        }
        // A moved caster may have been the top one: the least depth is taken over the chunks again.
        if (!changed->empty())
            refitTop(casters);
    }
    light->generation = changes.generation();
    light->used = calls_;
    return light->casters;
}

} // namespace penumbra::shadows
