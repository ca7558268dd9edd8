#include "penumbra/shadows/LightClusters.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/Sphere.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

namespace penumbra::shadows {
namespace {

constexpr std::uint32_t kMaxClustersPerAxis = 256;

// The camera's frame: x right, y up, z = view depth along forward; tangents of the half fields of view.
struct ViewFrame {
    glm::vec3 position;
    glm::vec3 right;
    glm::vec3 up;
    glm::vec3 forward;
    glm::vec2 tanHalf;

    explicit ViewFrame(const ShadowCamera& c)
        : position(c.position), right(glm::normalize(glm::cross(c.forward, c.up))), up(c.up), forward(c.forward)
    {
        const float t = std::tan(0.5f * c.fovY);
        tanHalf = {c.aspect * t, t};
    }
    glm::vec3 toView(glm::vec3 world) const
    {
        const glm::vec3 d = world - position;
        return {glm::dot(d, right), glm::dot(d, up), glm::dot(d, forward)};
    }
    glm::vec3 directionToView(glm::vec3 d) const { return {glm::dot(d, right), glm::dot(d, up), glm::dot(d, forward)}; }
};

struct Box {
    glm::vec3 min;
    glm::vec3 max;
};

bool sphereMeetsBox(const Sphere& s, const Box& b)
{
    const glm::vec3 nearest = glm::clamp(s.centre, b.min, b.max);
    const glm::vec3 d = nearest - s.centre;
    return glm::dot(d, d) <= s.radius * s.radius;
}

// The smallest sphere around a spot light's reach (a cone capped by its range sphere): for a half-angle up to 45
// degrees, centred range / (2 cos a) along the axis with that radius (the apex and the cap's rim lie on it); wider,
// centred range cos a along the axis with radius range sin a (the rim's circle). Bart Wronski, "Cull that cone!
// Improved cone/spotlight visibility tests for tiled and clustered lighting" (2017), for a flat cone; the cap's tip
// lies inside both.
Sphere spotBoundingSphere(glm::vec3 apex, glm::vec3 axis, float range, float angle)
{
    const float c = std::cos(angle);
    if (angle <= 0.25f * 3.14159265f) {
        const float t = range / (2.0f * c);
        return {apex + t * axis, t};
    }
    return {apex + range * c * axis, range * std::sin(angle)};
}

// False only when the sphere lies wholly outside the cone of half-angle `angle` from `apex` along `axis`, or beyond
// its range along the axis, or behind the apex (Wronski, above): the angle test is the distance from the sphere's
// centre to the cone's side, an underestimate where the apex is nearer.
// `cone` holds the cosine and sine of the half-angle.
bool sphereMeetsCone(const Sphere& s, glm::vec3 apex, glm::vec3 axis, float range, glm::vec2 cone)
{
    const glm::vec3 v = s.centre - apex;
    const float along = glm::dot(v, axis);
    const float across = std::sqrt(std::max(glm::dot(v, v) - along * along, 0.0f));
    const float toSide = cone.x * across - cone.y * along;
    return !(toSide > s.radius || along > s.radius + range || along < -s.radius);
}

std::uint32_t sliceOf(const LightClusterUniforms& g, float depth)
{
    const float slice = std::floor(std::log(std::max(depth, g.nearPlane)) * g.sliceScale + g.sliceBias);
    return static_cast<std::uint32_t>(std::clamp(slice, 0.0f, static_cast<float>(g.slices - 1)));
}

std::uint32_t tileOf(float ndc, bool fromTop, std::uint32_t tiles)
{
    const float t = std::floor((fromTop ? 1.0f - ndc : ndc + 1.0f) * 0.5f * static_cast<float>(tiles));
    return static_cast<std::uint32_t>(std::clamp(t, 0.0f, static_cast<float>(tiles - 1)));
}

float sliceStart(const LightClusterUniforms& g, std::uint32_t slice)
{
    return g.nearPlane * std::pow(g.farPlane / g.nearPlane, static_cast<float>(slice) / static_cast<float>(g.slices));
}

// Each cluster's view-space box, widened by kClusterBoxMargin. shaders/light_clusters.comp builds the same boxes from
// the same edges.
std::vector<Box> clusterBoxes(const LightClusterInputs& in)
{
    const LightClusterUniforms& g = in.grid;
    std::vector<Box> boxes(std::size_t(g.tilesX) * g.tilesY * g.slices);
    for (std::uint32_t slice = 0; slice < g.slices; ++slice) {
        const std::array<float, 2> depths{in.depths[slice], in.depths[slice + 1]};
        for (std::uint32_t y = 0; y < g.tilesY; ++y)
            for (std::uint32_t x = 0; x < g.tilesX; ++x) {
                Box box{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
                for (const float depth : depths)
                    for (const std::uint32_t cx : {x, x + 1})
                        for (const std::uint32_t cy : {y, y + 1}) {
                            const glm::vec2 ndc{in.edgesX[cx], in.edgesY[cy]};
                            const glm::vec3 p(ndc * in.tanHalf * depth, depth);
                            box.min = glm::min(box.min, p);
                            box.max = glm::max(box.max, p);
                        }
                const glm::vec3 margin(kClusterBoxMargin * depths[1]);
                boxes[x + g.tilesX * (y + g.tilesY * slice)] = {box.min - margin, box.max + margin};
            }
    }
    return boxes;
}

// The tiles a view-space sphere may cover: its box's corners projected (all in front of the camera), or the whole
// screen when the box reaches behind the near plane. Empty (x > z) when wholly off screen.
glm::uvec4 tileRange(const LightClusterUniforms& g, const ViewFrame& view, const Sphere& s)
{
    const glm::uvec4 all{0, 0, g.tilesX - 1, g.tilesY - 1};
    if (s.centre.z - s.radius <= 0.5f * g.nearPlane)
        return all;
    glm::vec2 low(INFINITY);
    glm::vec2 high(-INFINITY);
    for (const float dz : {-s.radius, s.radius})
        for (const float dx : {-s.radius, s.radius})
            for (const float dy : {-s.radius, s.radius}) {
                const glm::vec3 p = s.centre + glm::vec3(dx, dy, dz);
                const glm::vec2 ndc = glm::vec2(p) / (view.tanHalf * p.z);
                low = glm::min(low, ndc);
                high = glm::max(high, ndc);
            }
    if (high.x < -1.0f || low.x > 1.0f || high.y < -1.0f || low.y > 1.0f)
        return {1, 0, 0, 0};
    return {tileOf(low.x, false, g.tilesX), tileOf(high.y, true, g.tilesY), tileOf(high.x, false, g.tilesX),
            tileOf(low.y, true, g.tilesY)};
}

void validateClusterInputs(const ShadowCamera& camera, std::span<const ClusterLight> lights,
                           const LightClusterGridDesc& desc)
{
    for (const auto& [name, value] :
         {std::pair{"tilesX", desc.tilesX}, std::pair{"tilesY", desc.tilesY}, std::pair{"slices", desc.slices}})
        if (value == 0 || value > kMaxClustersPerAxis)
            throw rhi::Error(
                fmt::format("light clusters: {} is {}, allowed 1 to {}", name, value, kMaxClustersPerAxis));
    if (!(camera.nearPlane > 0.0f && camera.farPlane > camera.nearPlane && std::isfinite(camera.farPlane)))
        throw rhi::Error(fmt::format("light clusters: the camera's planes are {} and {}, allowed 0 < near < far "
                                     "(finite)",
                                     camera.nearPlane, camera.farPlane));
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const ClusterLight& l = lights[i];
        if (!(l.range > 0.0f && std::isfinite(l.range)))
            throw rhi::Error(
                fmt::format("light clusters: light {} has range {}, allowed a positive finite number", i, l.range));
        if (l.kind == LightKind::Spot && !(l.outerAngle > 0.0f && l.outerAngle < 0.5f * 3.14159265f))
            throw rhi::Error(fmt::format("light clusters: spot light {} has outer angle {}, allowed 0 to pi/2 "
                                         "(exclusive)",
                                         i, l.outerAngle));
    }
}

// The light's bound in the view (ClusterLightBound): its spheres, and the tiles and slices they may reach.
ClusterLightBound lightBound(const LightClusterUniforms& g, const ViewFrame& view, const ClusterLight& light)
{
    const Sphere reach{view.toView(light.position), light.range};
    const bool spot = light.kind == LightKind::Spot;
    const glm::vec3 axis = spot ? glm::normalize(view.directionToView(light.direction)) : glm::vec3(0.0f);
    const Sphere bound = spot ? spotBoundingSphere(reach.centre, axis, light.range, light.outerAngle) : reach;
    ClusterLightBound b;
    b.bound = glm::vec4(bound.centre, bound.radius);
    b.reach = glm::vec4(reach.centre, reach.radius);
    b.axis = glm::vec4(axis, spot ? 1.0f : 0.0f);
    if (spot)
        b.cone = {std::cos(light.outerAngle), std::sin(light.outerAngle), 0.0f, 0.0f};
    if (bound.centre.z + bound.radius < g.nearPlane || bound.centre.z - bound.radius > g.farPlane)
        return b;
    b.tiles = glm::ivec4(tileRange(g, view, bound));
    if (b.tiles.x <= b.tiles.z)
        b.slices =
            glm::ivec4(sliceOf(g, bound.centre.z - bound.radius), sliceOf(g, bound.centre.z + bound.radius), 0, 0);
    return b;
}

// Whether the light may reach a point of the cluster's box: inside its bounding sphere, its range sphere and (a
// spot light) its cone.
bool lightMeetsBox(const ClusterLightBound& light, const Box& box)
{
    const Sphere bound{glm::vec3(light.bound), light.bound.w};
    const Sphere reach{glm::vec3(light.reach), light.reach.w};
    if (light.axis.w == 0.0f)
        return sphereMeetsBox(bound, box);
    if (!sphereMeetsBox(bound, box) || !sphereMeetsBox(reach, box))
        return false;
    const Sphere around{0.5f * (box.min + box.max), 0.5f * glm::length(box.max - box.min)};
    return sphereMeetsCone(around, reach.centre, glm::vec3(light.axis), reach.radius, glm::vec2(light.cone));
}

} // namespace

std::uint32_t clusterIndex(const LightClusterUniforms& grid, glm::vec2 ndc, float depth)
{
    return tileOf(ndc.x, false, grid.tilesX) +
           grid.tilesX * (tileOf(ndc.y, true, grid.tilesY) + grid.tilesY * sliceOf(grid, depth));
}

std::optional<std::uint32_t> clusterAt(const ShadowCamera& camera, const LightClusterUniforms& grid, glm::vec3 world)
{
    const ViewFrame view(camera);
    const glm::vec3 p = view.toView(world);
    if (p.z < grid.nearPlane || p.z > grid.farPlane)
        return std::nullopt;
    const glm::vec2 ndc = glm::vec2(p) / (view.tanHalf * p.z);
    if (std::abs(ndc.x) > 1.0f || std::abs(ndc.y) > 1.0f)
        return std::nullopt;
    return clusterIndex(grid, ndc, p.z);
}

bool lightReaches(const ClusterLight& light, glm::vec3 world)
{
    const glm::vec3 d = world - light.position;
    const float distance = glm::length(d);
    if (distance > light.range)
        return false;
    return light.kind == LightKind::Point || glm::dot(d, light.direction) >= std::cos(light.outerAngle) * distance;
}

LightClusterInputs lightClusterInputs(const ShadowCamera& camera, std::span<const ClusterLight> lights,
                                      const LightClusterGridDesc& desc)
{
    validateClusterInputs(camera, lights, desc);
    LightClusterInputs in;
    LightClusterUniforms& g = in.grid;
    g.tilesX = desc.tilesX;
    g.tilesY = desc.tilesY;
    g.slices = desc.slices;
    g.nearPlane = camera.nearPlane;
    g.farPlane = camera.farPlane;
    g.sliceScale = static_cast<float>(g.slices) / std::log(g.farPlane / g.nearPlane);
    g.sliceBias = -std::log(g.nearPlane) * g.sliceScale;
    const ViewFrame view(camera);
    in.tanHalf = view.tanHalf;
    for (std::uint32_t x = 0; x <= g.tilesX; ++x)
        in.edgesX.push_back(2.0f * static_cast<float>(x) / static_cast<float>(g.tilesX) - 1.0f);
    for (std::uint32_t y = 0; y <= g.tilesY; ++y)
        in.edgesY.push_back(1.0f - 2.0f * static_cast<float>(y) / static_cast<float>(g.tilesY));
    for (std::uint32_t slice = 0; slice < g.slices; ++slice)
        in.depths.push_back(sliceStart(g, slice));
    in.depths.push_back(g.farPlane);
    in.lights.reserve(lights.size());
    for (const ClusterLight& light : lights) {
        const ClusterLightBound& b = in.lights.emplace_back(lightBound(g, view, light));
        if (b.tiles.x <= b.tiles.z && b.slices.x <= b.slices.y)
            in.entryBound += std::uint64_t(b.tiles.z - b.tiles.x + 1) * std::uint64_t(b.tiles.w - b.tiles.y + 1) *
                             std::uint64_t(b.slices.y - b.slices.x + 1);
    }
    return in;
}

LightClusters buildLightClusters(const ShadowCamera& camera, std::span<const ClusterLight> lights,
                                 const LightClusterGridDesc& desc)
{
    const LightClusterInputs in = lightClusterInputs(camera, lights, desc);
    LightClusters result;
    result.grid = in.grid;
    const LightClusterUniforms& g = in.grid;
    const std::vector<Box> boxes = clusterBoxes(in);
    std::vector<std::vector<std::uint32_t>> lists(boxes.size());
    for (std::uint32_t i = 0; i < in.lights.size(); ++i) {
        const ClusterLightBound& light = in.lights[i];
        for (int slice = light.slices.x; slice <= light.slices.y; ++slice)
            for (int y = light.tiles.y; y <= light.tiles.w; ++y)
                for (int x = light.tiles.x; x <= light.tiles.z; ++x) {
                    const auto c = static_cast<std::uint32_t>(x + int(g.tilesX) * (y + int(g.tilesY) * slice));
                    if (lightMeetsBox(light, boxes[c]))
                        lists[c].push_back(i);
                }
    }
    result.ranges.resize(lists.size());
    for (std::size_t c = 0; c < lists.size(); ++c) {
        result.ranges[c] = {static_cast<std::uint32_t>(result.lightIndices.size()),
                            static_cast<std::uint32_t>(lists[c].size())};
        result.lightIndices.insert(result.lightIndices.end(), lists[c].begin(), lists[c].end());
    }
    result.grid.indexCount = static_cast<std::uint32_t>(result.lightIndices.size());
    return result;
}

} // namespace penumbra::shadows
