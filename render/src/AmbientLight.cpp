#include "penumbra/render/AmbientLight.hpp"

#include "penumbra/rhi/Error.hpp"

#include <cmath>
#include <fmt/format.h>

namespace penumbra::render {
namespace {

void checkColor(const glm::vec3& c, const char* field)
{
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(c[i]) || c[i] < 0.0f)
            throw rhi::Error(
                fmt::format("{}: ({}, {}, {}): each component must be finite and at least 0", field, c.x, c.y, c.z));
}

} // namespace

void validate(const AmbientLight& ambient)
{
    checkColor(ambient.color, "ambient.color");
    if (ambient.ground)
        checkColor(*ambient.ground, "ambient.ground");
    if (!(ambient.intensity >= 0.0f && ambient.intensity <= kMaxAmbientIntensity))
        throw rhi::Error(
            fmt::format("ambient.intensity: {} is outside [0, {}]", ambient.intensity, kMaxAmbientIntensity));
}

} // namespace penumbra::render
