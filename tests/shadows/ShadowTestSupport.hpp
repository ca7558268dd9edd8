#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/shadows/ShadowCamera.hpp"

#include <array>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <random>
#include <string>

namespace penumbra::shadows::testing {

// Depth in [0, 1] and reversed-Z: the conventions of the planner tests that need only one.
inline const rhi::Conventions kZeroToOneReversed{rhi::DepthRange::ZeroToOne, true};

// The four conventions: depth range [0, 1] or [-1, 1], reversed-Z off or on.
inline std::array<rhi::Conventions, 4> allConventions()
{
    using rhi::DepthRange;
    return {rhi::Conventions{DepthRange::ZeroToOne, false}, rhi::Conventions{DepthRange::ZeroToOne, true},
            rhi::Conventions{DepthRange::MinusOneToOne, false}, rhi::Conventions{DepthRange::MinusOneToOne, true}};
}

inline std::string conventionName(const rhi::Conventions& c)
{
    return std::string(c.depthRange() == rhi::DepthRange::ZeroToOne ? "[0,1]" : "[-1,1]") +
           (c.reversedZ() ? " reversed" : "");
}

inline glm::vec3 randomUnit(std::mt19937& rng)
{
    std::normal_distribution<float> n(0.0f, 1.0f);
    for (;;) {
        const glm::vec3 v(n(rng), n(rng), n(rng));
        if (glm::length(v) > 1e-3f)
            return glm::normalize(v);
    }
}

// An orthonormal (forward, up) pair in a random orientation.
inline void randomOrientation(std::mt19937& rng, glm::vec3& forward, glm::vec3& up)
{
    forward = randomUnit(rng);
    glm::vec3 other = randomUnit(rng);
    while (std::abs(glm::dot(other, forward)) > 0.9f)
        other = randomUnit(rng);
    up = glm::normalize(other - forward * glm::dot(other, forward));
}

// A camera at `position` looking along `forward` (normalized here), its up the world's +y made square to it; the other
// fields as ShadowCamera's defaults.
inline ShadowCamera uprightCamera(glm::vec3 position, glm::vec3 forward)
{
    ShadowCamera camera;
    camera.position = position;
    camera.forward = glm::normalize(forward);
    camera.up = glm::normalize(glm::cross(glm::cross(camera.forward, glm::vec3(0, 1, 0)), camera.forward));
    return camera;
}

inline ShadowCamera randomCamera(std::mt19937& rng)
{
    std::uniform_real_distribution<float> position(-200.0f, 200.0f);
    std::uniform_real_distribution<float> fov(0.3f, 2.5f);
    std::uniform_real_distribution<float> aspect(0.5f, 3.0f);
    std::uniform_real_distribution<float> nearPlane(0.05f, 2.0f);
    ShadowCamera camera;
    camera.position = {position(rng), position(rng), position(rng)};
    randomOrientation(rng, camera.forward, camera.up);
    camera.fovY = fov(rng);
    camera.aspect = aspect(rng);
    camera.nearPlane = nearPlane(rng);
    camera.farPlane = 500.0f;
    return camera;
}

// Window depth as the rasterizer writes it for clip-space z of an orthographic projection (w = 1).
inline float rasterizerWindowDepth(const rhi::Conventions& c, const glm::vec4& clip)
{
    const float ndc = clip.z / clip.w;
    return c.depthRange() == rhi::DepthRange::ZeroToOne ? ndc : 0.5f * ndc + 0.5f;
}

} // namespace penumbra::shadows::testing
