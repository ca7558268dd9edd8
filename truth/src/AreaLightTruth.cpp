#include "penumbra/truth/AreaLightTruth.hpp"

#include "ParallelRows.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>

namespace penumbra::truth {
namespace {

// Chris Wellons's "lowbias32" integer hash ("Prospecting for Hash Functions", 2018).
std::uint32_t hash32(std::uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

float unitFloat(std::uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

// Shirley and Chiu's concentric map of [0, 1]^2 onto the unit disk: equal areas to equal areas, low distortion.
glm::vec2 concentricDisk(glm::vec2 u)
{
    const glm::vec2 p = 2.0f * u - 1.0f;
    if (p.x == 0.0f && p.y == 0.0f)
        return glm::vec2(0.0f);
    constexpr float kQuarterPi = 0.785398163f;
    if (std::abs(p.x) > std::abs(p.y)) {
        const float angle = kQuarterPi * (p.y / p.x);
        return p.x * glm::vec2(std::cos(angle), std::sin(angle));
    }
    const float angle = 2.0f * kQuarterPi - kQuarterPi * (p.x / p.y);
    return p.y * glm::vec2(std::cos(angle), std::sin(angle));
}

// Two unit vectors perpendicular to `axis` (unit) and to each other.
void perpendiculars(glm::vec3 axis, glm::vec3& t, glm::vec3& b)
{
    const glm::vec3 helper = std::abs(axis.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    t = glm::normalize(glm::cross(helper, axis));
    b = glm::cross(axis, t);
}

} // namespace

AreaLightSource areaLightOf(const scene::DirectionalLight& light)
{
    AreaLightSource source;
    source.atInfinity = true;
    source.direction = glm::normalize(light.direction);
    source.tanHalfAngle = std::tan(0.5f * light.angularDiameter * 0.0174532925f);
    return source;
}

namespace {

AreaLightSource diskAt(glm::vec3 position, float radius)
{
    AreaLightSource source;
    source.atInfinity = false;
    source.position = position;
    source.radius = radius;
    return source;
}

} // namespace

AreaLightSource areaLightOf(const scene::SpotLight& light) { return diskAt(light.position, light.sourceRadius); }

AreaLightSource areaLightOf(const scene::PointLight& light) { return diskAt(light.position, light.sourceRadius); }

SoftVisibilityMap traceAreaLightVisibility(const scene::Scene& scene, const RayCaster& shadowRays,
                                           const CpuGBuffer& gbuffer, const AreaLightSource& light,
                                           std::uint32_t raysPerSide, const TraceProgress& progress)
{
    if (shadowRays.kind() != RayKind::Shadow)
        throw std::invalid_argument("traceAreaLightVisibility needs a RayCaster built with RayKind::Shadow");
    SoftVisibilityMap map{gbuffer.width, gbuffer.height, std::vector<float>(gbuffer.samples.size(), 1.0f),
                          std::vector<std::uint8_t>(gbuffer.samples.size(), 0)};
    const float strata = static_cast<float>(raysPerSide);
    forEachRow(
        gbuffer.height,
        [&](std::uint32_t y) {
            for (std::size_t i = std::size_t(y) * gbuffer.width; i < std::size_t(y + 1) * gbuffer.width; ++i) {
                const GBufferSample& sample = gbuffer.samples[i];
                if (!sample.hit() || !scene.materialOf(scene.objects[sample.object]).receiveShadows)
                    continue;
                const glm::vec3 origin = shadowRayOrigin(sample);
                const glm::vec3 centre = light.atInfinity ? -light.direction : glm::normalize(light.position - origin);
                if (glm::dot(sample.normal, centre) <= 0.0f)
                    continue;
                glm::vec3 t, b;
                perpendiculars(centre, t, b);
                const float spread = light.atInfinity ? light.tanHalfAngle : light.radius;
                std::uint32_t reached = 0;
                for (std::uint32_t s = 0; s < raysPerSide * raysPerSide; ++s) {
                    const std::uint32_t h = hash32(static_cast<std::uint32_t>(i) * 0x9e3779b9u ^ hash32(s));
                    const glm::vec2 u{(static_cast<float>(s % raysPerSide) + unitFloat(h)) / strata,
                                      (static_cast<float>(s / raysPerSide) + unitFloat(hash32(h))) / strata};
                    const glm::vec2 d = spread * concentricDisk(u);
                    if (light.atInfinity) {
                        if (!shadowRays.occluded(origin, centre + d.x * t + d.y * b))
                            ++reached;
                    } else {
                        const glm::vec3 toPoint = light.position + d.x * t + d.y * b - origin;
                        const float distance = glm::length(toPoint);
                        if (!shadowRays.occluded(origin, toPoint / distance, distance))
                            ++reached;
                    }
                }
                map.lit[i] = static_cast<float>(reached) / (strata * strata);
                map.valid[i] = 1;
            }
        },
        progress);
    return map;
}

SoftTruthFigures compareSoftVisibility(const SoftVisibilityMap& truth, const RenderedVisibility& rendered, int margin)
{
    if (truth.width != rendered.width || truth.height != rendered.height)
        throw std::invalid_argument("compareSoftVisibility: the ray cast and the rendered picture differ in size");
    const auto w = static_cast<int>(truth.width), h = static_cast<int>(truth.height);
    const auto inPenumbra = [&](std::size_t i) {
        return truth.valid[i] && truth.lit[i] > kPenumbraEpsilon && truth.lit[i] < 1.0f - kPenumbraEpsilon;
    };
    std::vector<std::uint8_t> near(truth.lit.size(), 0);
    SoftTruthFigures figures;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * truth.width + std::size_t(x);
            if (!inPenumbra(i))
                continue;
            if (rendered.decided[i])
                ++figures.penumbraPixels;
            for (int dy = -margin; dy <= margin; ++dy)
                for (int dx = -margin; dx <= margin; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx >= 0 && ny >= 0 && nx < w && ny < h)
                        near[std::size_t(ny) * truth.width + std::size_t(nx)] = 1;
                }
        }
    double sum = 0.0;
    for (std::size_t i = 0; i < near.size(); ++i) {
        if (!near[i] || !truth.valid[i] || !rendered.decided[i])
            continue;
        const double error = std::abs(double(rendered.lit[i]) - double(truth.lit[i]));
        sum += error;
        figures.maxAbsError = std::max(figures.maxAbsError, error);
        ++figures.compared;
    }
    figures.meanAbsError = figures.compared == 0 ? 0.0 : sum / double(figures.compared);
    return figures;
}

} // namespace penumbra::truth
