#pragma once

#include "penumbra/rhi/CommandList.hpp"
#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/shadows/Bounds.hpp"
#include "penumbra/shadows/LocalLightProjection.hpp"
#include "penumbra/shadows/NormalOffset.hpp"
#include "penumbra/shadows/LocalShadowUniforms.hpp"
#include "penumbra/shadows/ShadowCamera.hpp"
#include "penumbra/shadows/ShadowAtlasLayout.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace penumbra::shadows {

// One spot light as the planner needs it: position, direction, cone, range, biases, filter.
struct SpotShadowInput {
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // unit cone axis, away from the light
    float range = 10.0f;
    float outerAngle = 0.6f; // half-angle, radians
    float strength = 1.0f;
    float normalBias = LightShadowDefaults::normalBias;
    float slopeScaleBias = LightShadowDefaults::slopeScaleBias;
    float nearPlane = 0.0f; // world units; 0: LocalShadowSettings::nearPlane x range
    std::optional<ShadowFilter> filter; // nullopt: the atlas's (LocalShadowSettings::filter)
    float sourceRadius = LightShadowDefaults::sourceRadius; // world units: the source size of soft filters
    NormalBiasSide normalBiasSide = NormalBiasSide::Receiver;
    std::optional<StaticShadowUpdate> staticUpdate; // nullopt: the settings' (StaticShadowSettings::update)
};

// One point light as the planner needs it: position, range, biases, filter.
struct PointShadowInput {
    glm::vec3 position{0.0f};
    float range = 10.0f;
    float strength = 1.0f;
    float normalBias = LightShadowDefaults::normalBias;
    float slopeScaleBias = LightShadowDefaults::slopeScaleBias;
    float nearPlane = 0.0f; // world units; 0: LocalShadowSettings::nearPlane x range
    std::optional<ShadowFilter> filter; // nullopt: the atlas's (LocalShadowSettings::filter)
    float sourceRadius = LightShadowDefaults::sourceRadius;
    NormalBiasSide normalBiasSide = NormalBiasSide::Receiver;
    std::optional<StaticShadowUpdate> staticUpdate; // nullopt: the settings' (StaticShadowSettings::update)
};

// One view a spot or point shadow is rendered from: an atlas tile, or one face of a cube map.
struct LocalShadowView {
    glm::mat4 projection{1.0f}; // the convention's perspective
    glm::mat4 viewProjection{1.0f};
    float slopeScaleBias = 0.0f;
    std::vector<std::uint32_t> casters; // indices into the caster bounds, the views' frustum culled
    CasterNormalOffset normalOffset; // the caster-side normal bias; none on the receiver side
};

// One tile of the local atlas: its view and viewport.
struct LocalAtlasTile {
    LocalShadowView view;
    std::uint32_t tile = 0;
    rhi::Viewport viewport;
};

// CubeMap mode: a point light's six faces, rendered into layers 6 x cube + face of the cube array.
struct ShadowCube {
    std::uint32_t lightIndex = 0;
    std::array<LocalShadowView, cubeFaceCount> faces;
};

// Why a spot or point light gets no shadow.
struct LocalShadowNote {
    LightKind kind = LightKind::Spot;
    std::uint32_t lightIndex = 0;
    std::string reason;
};

// The spot and point shadows of a frame: tiles or cubes per light, notes and the lit shader's uniforms.
struct LocalShadowPlan {
    ShadowAtlasLayout atlas{256, 0};
    std::vector<LocalAtlasTile> tiles; // in tile order
    std::vector<ShadowCube> cubes; // CubeMap mode only
    std::vector<int> spotTiles; // per spot light: its tile, or -1 without shadows
    std::vector<int> pointShadows; // per point light: first of its six tiles (Atlas mode) or its cube, or -1
    std::vector<LocalShadowNote> report;
    LocalShadowUniforms uniforms;
};

// Plans the spot and point shadows of a frame: spot lights first, then point lights, take tiles of the
// local atlas (one per spot light, six per point light in Atlas mode; up to 16) or, in CubeMap mode, a
// cube each (up to maxShadowCubes). A light that casts no shadow (strength 0), shadows nothing the camera can
// see (no caster's box meets its cone or range, or its range lies wholly beyond the shadow distance in the
// camera's view depth) or does not fit is listed in the report with the reason, never an exception, and takes
// no tile from the others. Throws rhi::Error only for settings that fail validate().
LocalShadowPlan planLocalShadows(const ShadowSettings& settings, const rhi::Conventions& conventions,
                                 const ShadowCamera& camera, std::span<const SpotShadowInput> spots,
                                 std::span<const PointShadowInput> points, std::span<const Bounds> casterBounds);

// Casters whose box meets a perspective view's frustum (a square field of view `fov` radians, near..far).
std::vector<std::uint32_t> cullCastersInFrustum(const glm::mat4& view, float fov, float nearPlane, float farPlane,
                                                std::span<const Bounds> casterBounds);

} // namespace penumbra::shadows
