#pragma once

#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shadows/Bounds.hpp"
#include "penumbra/shadows/DirectionalCascadeFit.hpp"
#include "penumbra/shadows/FrustumSliceSphere.hpp"
#include "penumbra/shadows/ShadowCamera.hpp"

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <optional>

namespace penumbra::shadows {

// What one shadow view's casters are tested against: a perspective frustum (a spot light, a point light's face; the
// camera's view, where the lit objects are culled on the GPU) or a cascade's light box, with the culling bias of the
// previous cascade (a sphere for the stable fit, a frustum slice for the close fit). The planner culls with
// casterInVolume; the GPU culling pass (shaders/caster_culling.comp) reads the same struct and mirrors it, line for
// line, so both give the same lists.
enum class CasterVolumeKind : std::int32_t {
    Frustum = 0, // a box meets the frustum unless all its corners lie outside one plane
    Cascade = 1, // the light box of a cascade without culling bias (the first cascade)
    CascadeBeyondSphere = 2, // and not wholly inside the previous cascade's culling sphere, scaled
    CascadeBeyondSlice = 3, // and not wholly inside the previous cascade's frustum slice, its depths scaled
};

// One view's volume, an element of the culling pass's storage block CasterVolumes (std430).
struct alignas(16) CasterVolume {
    glm::mat4 view{1.0f}; // Frustum: world to view space (looking down -z)
    glm::vec4 frustum{0.0f}; // Frustum: tan(fovX / 2), near, far, tan(fovY / 2)
    // Cascades: the light basis (LightBasis: right, up, direction) and the tile's square: snapped centre x, y, half
    // size, far depth.
    glm::vec4 right{0.0f};
    glm::vec4 up{0.0f};
    glm::vec4 direction{0.0f};
    glm::vec4 square{0.0f};
    glm::vec4 sphere{0.0f}; // CascadeBeyondSphere: the previous culling sphere's centre, its radius x culling factor
    // CascadeBeyondSlice: the camera's position and its slice's near distance, forward and scaled far distance, up
    // and tan(fovY / 2), right and tan(fovX / 2).
    glm::vec4 slicePosition{0.0f};
    glm::vec4 sliceForward{0.0f};
    glm::vec4 sliceUp{0.0f};
    glm::vec4 sliceRight{0.0f};
    CasterVolumeKind kind = CasterVolumeKind::Frustum;
};

inline constexpr std::array kCasterVolumeFields{
    PENUMBRA_SHADER_FIELD(CasterVolume, view),         PENUMBRA_SHADER_FIELD(CasterVolume, frustum),
    PENUMBRA_SHADER_FIELD(CasterVolume, right),        PENUMBRA_SHADER_FIELD(CasterVolume, up),
    PENUMBRA_SHADER_FIELD(CasterVolume, direction),    PENUMBRA_SHADER_FIELD(CasterVolume, square),
    PENUMBRA_SHADER_FIELD(CasterVolume, sphere),       PENUMBRA_SHADER_FIELD(CasterVolume, slicePosition),
    PENUMBRA_SHADER_FIELD(CasterVolume, sliceForward), PENUMBRA_SHADER_FIELD(CasterVolume, sliceUp),
    PENUMBRA_SHADER_FIELD(CasterVolume, sliceRight),   PENUMBRA_SHADER_FIELD(CasterVolume, kind),
};
inline constexpr shaders::ShaderStruct kCasterVolumeStruct{"CasterVolume", sizeof(CasterVolume), kCasterVolumeFields};
static_assert(shaders::matchesLayout(kCasterVolumeStruct, shaders::BlockLayout::Std430, true));

// A perspective view's frustum: square field of view `fov` radians, near..far.
CasterVolume frustumVolume(const glm::mat4& view, float fov, float nearPlane, float farPlane);
// A perspective view's frustum: vertical field of view `fovY` radians, `aspect` (width / height), near..far.
CasterVolume frustumVolume(const glm::mat4& view, float fovY, float aspect, float nearPlane, float farPlane);

// A close-fit cascade's region: the camera frustum between two view depths.
struct FrustumSlice {
    ShadowCamera camera;
    float nearDistance = 0.0f;
    float farDistance = 0.0f;
};

// A stable-fit cascade's light box; with the previous cascade's culling sphere, scaled by cullingFactor.
CasterVolume cascadeVolume(const DirectionalShadowCascade& cascade, const std::optional<Sphere>& previousCullingSphere,
                           float cullingFactor);
// A close-fit cascade's light box; with the previous cascade's slice, its depth range scaled by cullingFactor from its
// near end.
CasterVolume closeCascadeVolume(const DirectionalShadowCascade& cascade, const std::optional<FrustumSlice>& previous,
                                float cullingFactor);

// The light basis of a cascade volume.
LightBasis volumeBasis(const CasterVolume& volume);

// Cascades: whether the caster's light-space box (in the volume's basis) meets the tile's square in x and y and begins
// before its far plane (no near limit: casters in front of the near plane still cast, pancaked).
bool overlapsCascade(const Bounds& light, const CasterVolume& volume);
// Cascades: whether the previous cascade already holds the caster's shadow (the culling bias): its world box lies
// wholly inside the scaled sphere or slice. False for the first cascade and for frustums.
bool heldByPrevious(const Bounds& world, const CasterVolume& volume);
// Frustums: whether the box meets the frustum (it is culled where all 8 corners lie outside one of the six planes).
bool meetsFrustum(const Bounds& world, const CasterVolume& volume);

// Whether a caster with this world box is drawn into the volume's view: the planner's rule, and the reference the GPU
// culling pass mirrors.
bool casterInVolume(const Bounds& world, const CasterVolume& volume);

} // namespace penumbra::shadows
