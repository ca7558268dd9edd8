#include "penumbra/shadows/CasterVolume.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace penumbra::shadows {
namespace {

CasterVolume cascadeBox(const DirectionalShadowCascade& cascade)
{
    CasterVolume volume;
    volume.kind = CasterVolumeKind::Cascade;
    volume.right = glm::vec4(cascade.basis.right, 0.0f);
    volume.up = glm::vec4(cascade.basis.up, 0.0f);
    volume.direction = glm::vec4(cascade.basis.direction, 0.0f);
    volume.square = {cascade.snappedCentre, cascade.halfSize, cascade.farDepth};
    return volume;
}

// The box's farthest point from the centre lies within the radius.
bool insideSphere(const Bounds& box, glm::vec4 sphere)
{
    const glm::vec3 centre(sphere);
    const glm::vec3 farthest = glm::max(glm::abs(box.min - centre), glm::abs(box.max - centre));
    return glm::dot(farthest, farthest) <= sphere.w * sphere.w;
}

// Every corner lies inside the slice's side planes, at view depths from its near to its (scaled) far distance.
bool insideSlice(const Bounds& box, const CasterVolume& v)
{
    const glm::vec3 position(v.slicePosition), forward(v.sliceForward), up(v.sliceUp), right(v.sliceRight);
    for (const glm::vec3& corner : box.corners()) {
        const glm::vec3 offset = corner - position;
        const float depth = glm::dot(offset, forward);
        if (depth < v.slicePosition.w || depth > v.sliceForward.w ||
            std::abs(glm::dot(offset, right)) > depth * v.sliceRight.w ||
            std::abs(glm::dot(offset, up)) > depth * v.sliceUp.w)
            return false;
    }
    return true;
}

} // namespace

CasterVolume frustumVolume(const glm::mat4& view, float fov, float nearPlane, float farPlane)
{
    return frustumVolume(view, fov, 1.0f, nearPlane, farPlane);
}

CasterVolume frustumVolume(const glm::mat4& view, float fovY, float aspect, float nearPlane, float farPlane)
{
    CasterVolume volume;
    volume.kind = CasterVolumeKind::Frustum;
    volume.view = view;
    const float tanY = std::tan(0.5f * fovY);
    volume.frustum = {tanY * aspect, nearPlane, farPlane, tanY};
    return volume;
}

CasterVolume cascadeVolume(const DirectionalShadowCascade& cascade, const std::optional<Sphere>& previousCullingSphere,
                           float cullingFactor)
{
    CasterVolume volume = cascadeBox(cascade);
    if (previousCullingSphere) {
        volume.kind = CasterVolumeKind::CascadeBeyondSphere;
        volume.sphere = {previousCullingSphere->centre, previousCullingSphere->radius * cullingFactor};
    }
    return volume;
}

CasterVolume closeCascadeVolume(const DirectionalShadowCascade& cascade, const std::optional<FrustumSlice>& previous,
                                float cullingFactor)
{
    CasterVolume volume = cascadeBox(cascade);
    if (previous) {
        const ShadowCamera& camera = previous->camera;
        const float tanY = std::tan(0.5f * camera.fovY);
        const float farDistance =
            previous->nearDistance + (previous->farDistance - previous->nearDistance) * cullingFactor;
        volume.kind = CasterVolumeKind::CascadeBeyondSlice;
        volume.slicePosition = {camera.position, previous->nearDistance};
        volume.sliceForward = {camera.forward, farDistance};
        volume.sliceUp = {camera.up, tanY};
        volume.sliceRight = {glm::cross(camera.forward, camera.up), tanY * camera.aspect};
    }
    return volume;
}

LightBasis volumeBasis(const CasterVolume& volume)
{
    return {glm::vec3(volume.right), glm::vec3(volume.up), glm::vec3(volume.direction)};
}

bool overlapsCascade(const Bounds& light, const CasterVolume& v)
{
    const float h = v.square.z;
    return light.max.x >= v.square.x - h && light.min.x <= v.square.x + h && light.max.y >= v.square.y - h &&
           light.min.y <= v.square.y + h && light.min.z <= v.square.w;
}

bool heldByPrevious(const Bounds& world, const CasterVolume& volume)
{
    switch (volume.kind) {
    case CasterVolumeKind::CascadeBeyondSphere:
        return insideSphere(world, volume.sphere);
    case CasterVolumeKind::CascadeBeyondSlice:
        return insideSlice(world, volume);
    case CasterVolumeKind::Frustum:
    case CasterVolumeKind::Cascade:
        break;
    }
    return false;
}

bool meetsFrustum(const Bounds& world, const CasterVolume& volume)
{
    const float tx = volume.frustum.x, ty = volume.frustum.w;
    std::array<int, 6> outside{};
    for (const glm::vec3& corner : world.corners()) {
        const glm::vec3 p = glm::vec3(volume.view * glm::vec4(corner, 1.0f));
        const float depth = -p.z;
        outside[0] += depth < volume.frustum.y;
        outside[1] += depth > volume.frustum.z;
        outside[2] += p.x > depth * tx;
        outside[3] += -p.x > depth * tx;
        outside[4] += p.y > depth * ty;
        outside[5] += -p.y > depth * ty;
    }
    return std::none_of(outside.begin(), outside.end(), [](int n) { return n == 8; });
}

bool casterInVolume(const Bounds& world, const CasterVolume& volume)
{
    if (volume.kind == CasterVolumeKind::Frustum)
        return meetsFrustum(world, volume);
    return overlapsCascade(lightSpaceBounds(volumeBasis(volume), world), volume) && !heldByPrevious(world, volume);
}

} // namespace penumbra::shadows
