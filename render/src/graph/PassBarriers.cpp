#include "PassBarriers.hpp"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace penumbra::render {
namespace {

bool waitsOnShaderWrite(const StateChange& change)
{
    return rhi::hasFlag(change.before, rhi::ResourceState::ShaderWrite);
}

} // namespace

std::vector<std::vector<StateChange>> passBarriers(const std::vector<std::vector<ObjectUse>>& passes)
{
    std::vector<std::vector<StateChange>> barriers(passes.size());
    std::unordered_map<const void*, rhi::ResourceState> states; // what the passes so far left each object in
    for (std::size_t pass = 0; pass < passes.size(); ++pass) {
        std::vector<StateChange>& batch = barriers[pass];
        const auto add = [&](const ObjectUse& use) {
            const auto same =
                std::find_if(batch.begin(), batch.end(), [&](const StateChange& c) { return c.object == use.object; });
            if (same == batch.end())
                batch.push_back({use.object, states[use.object], use.state});
            else
                same->after |= use.state;
        };
        for (const ObjectUse& use : passes[pass])
            add(use);
        const bool waits = std::any_of(batch.begin(), batch.end(), waitsOnShaderWrite);
        std::unordered_set<const void*> used; // by this pass and the later ones looked at so far
        for (std::size_t later = pass; waits && later < passes.size(); ++later) {
            for (const ObjectUse& use : passes[later])
                if (later > pass && !used.contains(use.object) &&
                    rhi::hasFlag(states[use.object], rhi::ResourceState::ShaderWrite))
                    add(use);
            for (const ObjectUse& use : passes[later])
                used.insert(use.object);
        }
        for (const StateChange& change : batch)
            states[change.object] = change.after;
    }
    return barriers;
}

} // namespace penumbra::render
