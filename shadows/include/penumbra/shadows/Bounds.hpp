#pragma once

#include <array>
#include <glm/vec3.hpp>

namespace penumbra::shadows {

// Axis-aligned world-space box of a shadow caster.
struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};

    // The box's eight corners.
    std::array<glm::vec3, 8> corners() const
    {
        return {{{min.x, min.y, min.z},
                 {max.x, min.y, min.z},
                 {min.x, max.y, min.z},
                 {max.x, max.y, min.z},
                 {min.x, min.y, max.z},
                 {max.x, min.y, max.z},
                 {min.x, max.y, max.z},
                 {max.x, max.y, max.z}}};
    }
};

} // namespace penumbra::shadows
