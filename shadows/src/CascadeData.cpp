#include "penumbra/shadows/CascadeData.hpp"

namespace penumbra::shadows {

CascadeData cascadeData(const Sphere& cullingSphere, float texelSize, ShadowFilter filter, float farDepth)
{
    const float filterWorldSize = texelSize * normalBiasFilterFactor(filter);
    const float shrunk = cullingSphere.radius - filterWorldSize;
    const float shrunkSquared = shrunk * shrunk;
    return {glm::vec4(cullingSphere.centre, shrunkSquared),
            glm::vec4(1.0f / shrunkSquared, filterWorldSize * 1.4142136f, texelSize, farDepth)};
}

} // namespace penumbra::shadows
