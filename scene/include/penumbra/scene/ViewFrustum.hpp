#pragma once

#include "penumbra/scene/Camera.hpp"
#include "penumbra/scene/Geometry.hpp"

#include <array>
#include <glm/vec4.hpp>

namespace penumbra::scene {

// The six planes of a perspective camera's view volume in world space, each as (inward normal, offset): a point p is
// on the inner side where dot(normal, p) + offset >= 0.
class ViewFrustum {
public:
    // The six planes of `camera`'s view at `aspect` (width / height).
    ViewFrustum(const Camera& camera, float aspect);

    // False only where the box lies wholly outside one plane, so no fragment of what it bounds can be drawn; boxes
    // that cross a corner of the volume without meeting it are kept (the usual conservative test, Akenine-Moller et
    // al., "Real-Time Rendering", 4th edition, section 22.14.3, "Plane/Box Intersection").
    bool mayShow(const Bounds& box) const;

private:
    std::array<glm::vec4, 6> planes_;
};

} // namespace penumbra::scene
