#pragma once

#include <glm/vec3.hpp>

namespace penumbra::shadows {

// A sphere: centre and radius.
struct Sphere {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};

} // namespace penumbra::shadows
