#pragma once

#include "penumbra/shadows/FrustumSliceSphere.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <glm/vec4.hpp>

namespace penumbra::shadows {

// What the lit shader needs per cascade (the document's SetCascadeData).
struct CascadeData {
    // Culling sphere shrunk by the filter size, r' = r - texelSize * filterFactor, so filter taps
    // of a selected receiver stay inside the tile: (centre, r'^2) for selection.
    glm::vec4 selectionSphere{0.0f};
    // (1 / r'^2, texelSize * filterFactor * sqrt 2, texelSize, farDepth): the cascade fade scale, the normal
    // bias in world units (sqrt 2: a texel's diagonal is the worst case), the texel's world size (soft shadows'
    // penumbrae in world units) and the view depth where the cascade ends (the close fit's selection and fade).
    glm::vec4 data{0.0f};
};

CascadeData cascadeData(const Sphere& cullingSphere, float texelSize, ShadowFilter filter, float farDepth);

} // namespace penumbra::shadows
