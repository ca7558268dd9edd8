#include "penumbra/shadows/CascadeData.hpp"

namespace penumbra::shadows {

CascadeData cascadeData(const Sphere& cullingSphere, float texelSize, ShadowFilter filter, float farDepth)
{
    const float filterWorldSize = texelSize * normalBiasFilterFactor(filter);
    const float shrunk = cullingSphere.radius - filterWorldSize;
    const float shrunkSquared = shrunk * shrunk;
    return {.selectionCentre = cullingSphere.centre,
            .selectionRadiusSquared = shrunkSquared,
            .fadeScale = 1.0f / shrunkSquared,
            .normalBias = filterWorldSize * 1.4142136f,
            .texelWorldSize = texelSize,
            .farDepth = farDepth};
}

} // namespace penumbra::shadows
