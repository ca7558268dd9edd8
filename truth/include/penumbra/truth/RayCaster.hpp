#pragma once

#include "penumbra/scene/Scene.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>

namespace penumbra::truth {

// Which surfaces a RayCaster sees, by material:
//                  CasterMode::On   Clip                         Dither                      Off
//   Shadow         solid            holes: alpha < alphaCutoff   holes: alpha < 0.5          absent
//   Camera         solid            holes: alpha < alphaCutoff   solid                       solid
// alpha = materialAlpha(material, uv at the hit, its base colour texture). Shadow is the ground truth for shadow maps:
// a dithered caster's expected coverage is its alpha, which a binary answer cannot give, so
// occluded() and closestHit() threshold it at kDitherShadowThreshold and occlusion() reports it
// apart, with its alpha. Camera is what the lit pass draws: Clip materials are
// clipped there too, Dither ones are drawn solid. Per object, Object::castShadows Off removes the
// object from Shadow rays and ShadowsOnly from Camera rays.
// Faces are culled as the passes cull them: Camera rays see only the front (CCW) side of
// single-sided materials, Shadow rays only the light-facing side of single-sided casters (the
// side a ray towards the light leaves through); doubleSided materials, and for Shadow rays
// ShadowCasting::TwoSided objects, are seen from both sides.
enum class RayKind : std::uint8_t { Shadow, Camera };

inline constexpr float kDitherShadowThreshold = 0.5f;

// Where a ray met a triangle.
struct Hit {
    float distance; // world units along the (normalised) direction
    std::uint32_t object; // index into Scene::objects
    std::uint32_t triangle; // triangle index within the object's mesh (indices[3 * triangle ...])
    glm::vec2 barycentrics; // weights of the triangle's 2nd and 3rd vertex; the 1st gets 1 - x - y
    glm::vec3 normal; // unit world normal of the triangle's front (CCW) side, whichever side was hit
};

// What a shadow ray meets on its way to the light. A dithered caster's shadow map keeps a texel
// where its alpha reaches the texel's dither threshold, one threshold per texel for every layer,
// so the light it lets through is 1 - the largest alpha among the dithered surfaces crossed.
struct Occlusion {
    bool solid = false; // blocked by a surface that is not dithered
    // The largest alpha of the dithered surfaces crossed, 0 for none; where solid, only of those
    // met before the solid blocker was found.
    float ditherCoverage = 0.0f;
};

// Ground-truth visibility on the CPU: world-space triangles of a scene in a BVH (binned
// SAH). The caster copies what it needs; the scene may change or go away afterwards.
// Shadow rays must travel towards the light (the culling above assumes it); directions
// need not be unit (they are normalised), and hits count at
// 0 < distance <= maxDistance, so rays leaving a surface must start slightly off it.
class RayCaster {
public:
    // Builds the BVH over every object of `scene` that rays of `kind` can meet.
    explicit RayCaster(const scene::Scene& scene, RayKind kind = RayKind::Shadow);
    ~RayCaster();
    // Moves the BVH.
    RayCaster(RayCaster&&) noexcept;
    // Moves the BVH.
    RayCaster& operator=(RayCaster&&) noexcept;

    // Which rays the caster traces (shadow or camera), which decides culling and what is skipped.
    RayKind kind() const;
    // Triangles in the BVH.
    std::uint32_t triangleCount() const;

    // Any hit; stops at the first one.
    bool occluded(const glm::vec3& origin, const glm::vec3& direction,
                  float maxDistance = std::numeric_limits<float>::infinity()) const;
    // Solid blockers and dithered ones apart, with the dithered ones' alpha instead of its threshold.
    Occlusion occlusion(const glm::vec3& origin, const glm::vec3& direction,
                        float maxDistance = std::numeric_limits<float>::infinity()) const;
    // The nearest triangle along the ray within maxDistance, or nullopt.
    std::optional<Hit> closestHit(const glm::vec3& origin, const glm::vec3& direction,
                                  float maxDistance = std::numeric_limits<float>::infinity()) const;

private:
    struct Data;
    std::unique_ptr<Data> data_;
};

} // namespace penumbra::truth
