#pragma once

#include "penumbra/shadows/CasterChanges.hpp"
#include "penumbra/shadows/DirectionalShadowUniforms.hpp"
#include "penumbra/shadows/LightBasis.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace penumbra::shadows {

// The casters' light-space boxes of each directional light (lightSpaceCasters), kept from frame to frame: for a light
// whose direction is last frame's, only the casters changed since (CasterChanges) are transformed again instead of
// every caster, which at 10^5 instances was the larger part of planning.
class LightSpaceCache {
public:
    // Lights whose boxes are kept (the least recently asked for goes first): one planning asks for every shadowed
    // light's, and holds them all.
    static constexpr std::size_t kKeptLights = maxShadowedDirectionalLights;

    LightSpaceCache() { lights_.reserve(kKeptLights); }

    // lightSpaceCasters(lightBasis(direction), world), element for element; `changes` is the log of the list `world`
    // comes from. Stays valid while no more than kKeptLights - 1 other directions are asked for.
    const LightSpaceCasters& casters(glm::vec3 direction, std::span<const Bounds> world, const CasterChanges& changes);

private:
    struct Light {
        glm::vec3 direction{0.0f};
        std::uint64_t generation = 0; // that of `changes` when the boxes were brought up to date
        std::uint64_t used = 0; // the call that asked for it last
        LightSpaceCasters casters;
    };
    std::vector<Light> lights_;
    std::uint64_t calls_ = 0;
};

} // namespace penumbra::shadows
