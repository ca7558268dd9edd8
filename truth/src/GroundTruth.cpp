#include "penumbra/truth/GroundTruth.hpp"

#include "MeshSurfaces.hpp"
#include "ParallelRows.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace penumbra::truth {
namespace {

// World normal from the mesh's vertex normals at the hit. The inverse transpose keeps
// normals perpendicular under any affine transform, not only the rigid ones of the test scene.
glm::vec3 interpolatedNormal(const scene::Scene& scene, const Hit& hit)
{
    const scene::Object& object = scene.objects[hit.object];
    const scene::MeshData& mesh = scene.meshOf(object);
    const std::uint32_t* index = &mesh.indices[3 * std::size_t(hit.triangle)];
    const glm::vec3 local = (1.0f - hit.barycentrics.x - hit.barycentrics.y) * mesh.vertices[index[0]].normal +
                            hit.barycentrics.x * mesh.vertices[index[1]].normal +
                            hit.barycentrics.y * mesh.vertices[index[2]].normal;
    return glm::normalize(glm::transpose(glm::inverse(glm::mat3(object.transform))) * local);
}

glm::vec2 interpolatedUv(const scene::Scene& scene, const Hit& hit)
{
    const scene::MeshData& mesh = scene.meshOf(scene.objects[hit.object]);
    const std::uint32_t* index = &mesh.indices[3 * std::size_t(hit.triangle)];
    return (1.0f - hit.barycentrics.x - hit.barycentrics.y) * mesh.vertices[index[0]].uv +
           hit.barycentrics.x * mesh.vertices[index[1]].uv + hit.barycentrics.y * mesh.vertices[index[2]].uv;
}

} // namespace

Ray primaryRay(const scene::Camera& camera, std::uint32_t width, std::uint32_t height, float px, float py)
{
    const float ndcX = 2.0f * px / static_cast<float>(width) - 1.0f;
    const float ndcY = 1.0f - 2.0f * py / static_cast<float>(height);
    const float tanHalfFov = std::tan(0.5f * camera.fovY);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    // View-space direction (x, y, -1) taken to world space with the inverse of view().
    const glm::mat3 viewToWorld = glm::inverse(glm::mat3(camera.view()));
    const glm::vec3 direction =
        glm::normalize(viewToWorld * glm::vec3(ndcX * tanHalfFov * aspect, ndcY * tanHalfFov, -1.0f));
    // Distances along this ray are view depth / cos(angle to the forward axis).
    const float depthPerDistance = glm::dot(direction, glm::normalize(camera.forward));
    const float nearDistance = camera.nearPlane / depthPerDistance;
    return {camera.position + direction * nearDistance, direction,
            (camera.farPlane - camera.nearPlane) / depthPerDistance};
}

CpuGBuffer traceGBuffer(const scene::Scene& scene, const RayCaster& cameraRays, const scene::Camera& camera,
                        std::uint32_t width, std::uint32_t height, const TraceProgress& progress)
{
    if (cameraRays.kind() != RayKind::Camera)
        throw std::invalid_argument("traceGBuffer needs a RayCaster built with RayKind::Camera");
    CpuGBuffer gbuffer{width, height, std::vector<GBufferSample>(std::size_t(width) * height)};
    const glm::vec3 forward = glm::normalize(camera.forward);
    std::vector<std::vector<std::uint32_t>> surfaces;
    surfaces.reserve(scene.meshes.size());
    for (const scene::MeshData& mesh : scene.meshes)
        surfaces.push_back(meshSurfaces(mesh));
    forEachRow(
        height,
        [&](std::uint32_t y) {
            for (std::uint32_t x = 0; x < width; ++x) {
                const Ray ray =
                    primaryRay(camera, width, height, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
                const std::optional<Hit> hit = cameraRays.closestHit(ray.origin, ray.direction, ray.maxDistance);
                if (!hit)
                    continue;
                GBufferSample& sample = gbuffer.samples[std::size_t(y) * width + x];
                sample.object = hit->object;
                sample.triangle = hit->triangle;
                sample.surface = surfaces[scene.objects[hit->object].mesh][hit->triangle];
                sample.position = ray.origin + hit->distance * ray.direction;
                sample.frontFacing = glm::dot(hit->normal, ray.direction) < 0.0f;
                const float towardsCamera = sample.frontFacing ? 1.0f : -1.0f;
                sample.normal = towardsCamera * hit->normal;
                sample.shadingNormal = towardsCamera * interpolatedNormal(scene, *hit);
                sample.uv = interpolatedUv(scene, *hit);
                sample.viewDepth = glm::dot(sample.position - camera.position, forward);
            }
        },
        progress);
    return gbuffer;
}

ShadowRayFrom raysTowards(const scene::DirectionalLight& light)
{
    const glm::vec3 towardsLight = -glm::normalize(light.direction);
    return [towardsLight](glm::vec3 origin) {
        return ShadowRay{origin, towardsLight, std::numeric_limits<float>::infinity()};
    };
}

ShadowRayFrom raysTowards(glm::vec3 lightPosition)
{
    return [lightPosition](glm::vec3 origin) {
        const glm::vec3 toLight = lightPosition - origin;
        const float distance = glm::length(toLight);
        return ShadowRay{origin, toLight / distance, distance};
    };
}

LightVisibility visibilityOf(const Occlusion& occlusion)
{
    if (occlusion.solid)
        return LightVisibility::Shadowed;
    return occlusion.ditherCoverage > 0.0f ? LightVisibility::Dithered : LightVisibility::Lit;
}

glm::vec3 shadowRayOrigin(const GBufferSample& sample, float normalOffset)
{
    return sample.position + normalOffset * sample.normal;
}

LightVisibilityMask traceVisibility(const scene::Scene& scene, const RayCaster& shadowRays, const CpuGBuffer& gbuffer,
                                    const ShadowRayFrom& rayFrom, float normalOffset, const TraceProgress& progress)
{
    if (shadowRays.kind() != RayKind::Shadow)
        throw std::invalid_argument("traceVisibility needs a RayCaster built with RayKind::Shadow");
    LightVisibilityMask mask{gbuffer.width, gbuffer.height,
                             std::vector<LightVisibility>(gbuffer.samples.size(), LightVisibility::Background),
                             std::vector<std::uint32_t>(gbuffer.samples.size(), kNoObject),
                             std::vector<float>(gbuffer.samples.size(), 0.0f)};
    forEachRow(
        gbuffer.height,
        [&](std::uint32_t y) {
            for (std::size_t i = std::size_t(y) * gbuffer.width; i < std::size_t(y + 1) * gbuffer.width; ++i) {
                const GBufferSample& sample = gbuffer.samples[i];
                if (!sample.hit())
                    continue;
                const ShadowRay ray = rayFrom(shadowRayOrigin(sample, normalOffset));
                if (!scene.receivesShadows(scene.objects[sample.object]))
                    mask.pixels[i] = LightVisibility::NotReceiving;
                else if (glm::dot(sample.normal, ray.direction) <= 0.0f)
                    mask.pixels[i] = LightVisibility::FacingAway;
                else if (const Occlusion occlusion = shadowRays.occlusion(ray.origin, ray.direction, ray.maxDistance);
                         !occlusion.solid) {
                    mask.pixels[i] = visibilityOf(occlusion);
                    mask.ditherCoverage[i] = occlusion.ditherCoverage;
                } else {
                    mask.pixels[i] = LightVisibility::Shadowed;
                    const std::optional<Hit> blocker =
                        shadowRays.closestHit(ray.origin, ray.direction, ray.maxDistance);
                    mask.blockers[i] = blocker ? blocker->object : kNoObject;
                }
            }
        },
        progress);
    return mask;
}

LightVisibilityMask traceLightVisibility(const scene::Scene& scene, const RayCaster& shadowRays,
                                         const CpuGBuffer& gbuffer, const scene::DirectionalLight& light,
                                         float normalOffset)
{
    return traceVisibility(scene, shadowRays, gbuffer, raysTowards(light), normalOffset);
}

LightVisibilityMask tracePositionalLightVisibility(const scene::Scene& scene, const RayCaster& shadowRays,
                                                   const CpuGBuffer& gbuffer, glm::vec3 lightPosition,
                                                   float normalOffset)
{
    return traceVisibility(scene, shadowRays, gbuffer, raysTowards(lightPosition), normalOffset);
}

} // namespace penumbra::truth
