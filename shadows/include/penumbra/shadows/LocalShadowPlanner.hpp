#pragma once

#include "penumbra/rhi/CommandList.hpp"
#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/shadows/Bounds.hpp"
#include "penumbra/shadows/CasterVolume.hpp"
#include "penumbra/shadows/LocalLightProjection.hpp"
#include "penumbra/shadows/NormalOffset.hpp"
#include "penumbra/shadows/LocalShadowUniforms.hpp"
#include "penumbra/shadows/ShadowAtlasPacker.hpp"
#include "penumbra/shadows/ShadowCamera.hpp"
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
    float intensity = 1.0f; // the light's brightness (its intensity times its colour's largest channel)
    std::optional<float> shadowResolution; // texels; nullopt: LocalShadowSettings::tileResolution
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
    float intensity = 1.0f; // the light's brightness (its intensity times its colour's largest channel)
    std::optional<float> shadowResolution; // texels; nullopt: LocalShadowSettings::tileResolution
};

// One view a spot or point shadow is rendered from: an atlas tile, or one face of a cube map.
struct LocalShadowView {
    glm::mat4 projection{1.0f}; // the convention's perspective
    glm::mat4 viewProjection{1.0f};
    float slopeScaleBias = 0.0f;
    float depthBias = 0.0f; // the constant one, LocalShadowSettings::depthBias
    // Indices into the caster bounds, the views' frustum culled; left empty for the atlas tiles where the casters
    // are culled on the GPU (culledOnGpu), which tests them against `volume`.
    std::vector<std::uint32_t> casters;
    CasterNormalOffset normalOffset; // the caster-side normal bias; none on the receiver side
    CasterVolume volume; // the view's frustum, which `casters` were culled with
};

// One tile of the local atlas: its view and viewport (its place and size in the atlas).
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

// Why a spot or point light gets no shadow, or a smaller one than it asked for.
struct LocalShadowNote {
    LightKind kind = LightKind::Spot;
    std::uint32_t lightIndex = 0;
    std::string reason;
};

// Where the packer put each light's tiles (ShadowAtlasPacker), kept from frame to frame so that a light whose inputs
// stay put keeps its tiles. Spot light i is packer light 2i, point light i 2i + 1.
struct LocalAtlasAllocation {
    ShadowAtlasPackerSettings packer;
    ShadowAtlasPack pack; // every light's tiles, and how full and fragmented the atlas is
};

// The packer light of spot light `index`, and of point light `index`.
constexpr std::uint32_t spotPackerId(std::uint32_t index) { return 2 * index; }
constexpr std::uint32_t pointPackerId(std::uint32_t index) { return 2 * index + 1; }

// The spot and point shadows of a frame: tiles or cubes per light, notes and the lit shader's data.
struct LocalShadowPlan {
    std::uint32_t atlasSize = 0; // texels per side of the local atlas (LocalShadowSettings::atlasSize)
    std::vector<LocalAtlasTile> tiles; // in tile order
    std::vector<LocalAtlasTileData> tileData; // per tile, as the lit shader reads it (storage block LocalShadowTiles)
    std::vector<ShadowCube> cubes; // CubeMap mode only
    std::vector<int> spotTiles; // per spot light: its tile, or -1 without shadows
    std::vector<int> pointShadows; // per point light: first of its six tiles (Atlas mode) or its cube, or -1
    std::vector<LocalShadowNote> report; // lights without a realtime shadow, and why
    std::vector<LocalShadowNote> lowered; // lights whose tiles are smaller than they asked for, and why
    LocalAtlasAllocation allocation; // the next frame's starting point
    LocalShadowUniforms uniforms;
};

// Plans the spot and point shadows of a frame: each light that casts shadows asks for a tile size (one tile for a
// spot light, six for a point light in Atlas mode) from its own shadowResolution (or the settings' tileResolution)
// times its importance on screen (localShadowRequest), and ShadowAtlasPacker places them in the atlas, starting from
// `previous` (the last frame's allocation: tiles stay put while requests stay within the hysteresis). When the atlas
// runs out of room, tiles are lowered down to local.minTileResolution before a light loses its shadow (`lowered`,
// `report`). In CubeMap mode point lights take a cube each (up to maxShadowCubes). A light that casts no shadow
// (strength 0), shadows nothing the camera can see (no caster's box meets its cone or range, or its range lies wholly
// beyond the shadow distance in the camera's view depth) or does not fit is listed in the report with the reason,
// never an exception, and takes no tile from the others. Throws rhi::Error only for settings that fail validate().
LocalShadowPlan planLocalShadows(const ShadowSettings& settings, const rhi::Conventions& conventions,
                                 const ShadowCamera& camera, std::span<const SpotShadowInput> spots,
                                 std::span<const PointShadowInput> points, std::span<const Bounds> casterBounds,
                                 const LocalAtlasAllocation& previous = {});

// Casters whose box meets a perspective view's frustum (a square field of view `fov` radians, near..far).
std::vector<std::uint32_t> cullCastersInFrustum(const glm::mat4& view, float fov, float nearPlane, float farPlane,
                                                std::span<const Bounds> casterBounds);

} // namespace penumbra::shadows
