#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace penumbra::shadows {

// A spot or point light that may take contact shadows (ContactShadowSettings::localLights): one with a shadow this
// frame whose reach the camera may see, where it is and how far it reaches.
struct ContactLightCandidate {
    std::uint32_t light = 0; // the caller's index
    glm::vec3 position{0.0f};
    float range = 0.0f;
};

// The spot and point lights the contact march goes towards this frame: of `candidates`, the `count` nearest
// `camera`, by the distance to the sphere each reaches (0 from inside it), then to the light itself, then the lower
// index; their `light` indices in that order. A fixed few per frame rather than per pixel keeps the march's cost and
// its texture's bits bounded, and every pixel agrees on which light each bit is; contact shadows are a near-field
// detail, so the lights reaching the camera's surroundings matter most.
std::vector<std::uint32_t> nearestContactLights(glm::vec3 camera, std::span<const ContactLightCandidate> candidates,
                                                std::uint32_t count);

} // namespace penumbra::shadows
