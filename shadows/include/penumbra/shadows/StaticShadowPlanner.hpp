#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/shadows/Bounds.hpp"
#include "penumbra/shadows/DirectionalShadowPlanner.hpp"
#include "penumbra/shadows/LocalShadowPlanner.hpp"
#include "penumbra/shadows/ShadowAtlasLayout.hpp"
#include "penumbra/shadows/ShadowCasterDraws.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"
#include "penumbra/shadows/StaticShadowUniforms.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace penumbra::shadows {

// A shadow view as no convention sees it: the light's view and its frustum, what a bake records and checks.
struct ShadowFrustum {
    glm::mat4 view{1.0f}; // world -> light view, looking down -z
    bool perspective = false;
    float extent = 0.0f; // half the side of the orthographic square, or the perspective field of view (radians)
    float nearPlane = 0.0f; // view depths along -z
    float farPlane = 0.0f;
};

// One tile of a static shadow map and what is drawn into it: the static casters the view may see.
struct StaticShadowTile : ShadowTileDraw {
    glm::mat4 projection{1.0f}; // the convention's, view.viewProjection = projection * frustum.view
    ShadowFrustum frustum;
};

// Light-space depth along the view's -z of a stored window depth, and back: how bakes store depth whatever the
// convention (depth range, reversed-Z) that rendered them. `projection` is the tile's.
float linearShadowDepth(float windowDepth, const glm::mat4& projection, const rhi::Conventions& conventions);
float windowShadowDepth(float linearDepth, const glm::mat4& projection, const rhi::Conventions& conventions);

// The static shadow map of one light: one tile of the static directional atlas (an orthographic view over every
// static caster), one tile of the static local atlas (a spot light's cone) or six (a point light's faces).
struct StaticShadowMap {
    LightKind kind = LightKind::Directional;
    std::uint32_t lightIndex = 0; // into the planner's input lights of that kind
    std::vector<StaticShadowTile> tiles;
    float texelSize = 0.0f; // directional maps: the world size of a texel
    StaticShadowUpdate update = StaticShadowUpdate::OnChange; // the light's own mode, or the settings'
    std::uint32_t litIndex = 0; // its entry in the uniforms' directionalLights or the plan's localLightMaps
};

// Why a light gets no static map.
struct StaticShadowNote {
    LightKind kind = LightKind::Directional;
    std::uint32_t lightIndex = 0;
    std::string reason;
};

// The static maps of a frame: both static atlases' layouts, each light's map, notes and uniforms.
struct StaticShadowPlan {
    ShadowAtlasLayout directionalAtlas{256, 0};
    ShadowAtlasLayout localAtlas{256, 0};
    std::vector<StaticShadowMap> maps; // directional lights first, then spot, then point lights
    std::vector<StaticShadowNote> report;
    StaticShadowUniforms uniforms;
    // Per spot light, then point light (the lit pass's local index). The lit shader reads it from the local light
    // texture (render::LocalLightRecord::staticTile, staticStrength).
    std::vector<StaticLocalLightMap> localLightMaps;
};

// The casters whose depth the static maps hold: indices into the planner's caster bounds.
struct StaticCasters {
    std::span<const Bounds> bounds; // every caster's
    std::span<const std::uint32_t> indices; // the static ones, ascending
};

// The update mode of a light: its own, or the settings'.
inline StaticShadowUpdate staticUpdateOf(std::optional<StaticShadowUpdate> light, const ShadowSettings& settings)
{
    return light.value_or(settings.staticMaps.update);
}

// Plans the static shadow maps (settings.staticMaps) of every light that casts shadows with strength > 0, whose
// update mode (its own staticUpdate, or the settings') is not EveryFrame, and has a static caster in reach, whatever
// the camera sees: directional lights (up to 4) take a tile of the static directional atlas fitted around the static
// casters' bounding sphere (the stable fit of a cascade, so its texels stay put while nothing static moves); spot and
// point lights take one and six tiles of the static local atlas (up to maxStaticLocalTiles), with the projections of
// their realtime tiles. Lights that do not fit are listed in the report. A map is filtered as the light's realtime
// shadow is (its own filter or the atlas's; the Poisson and PCSS filters with the soft data of StaticShadowUniforms),
// with the same normal bias scaled to the map's texels. Uniform entries follow the lit pass's light order:
// directional lights, then spot lights, then point lights. Throws rhi::Error only for settings that fail validate().
StaticShadowPlan planStaticShadows(const ShadowSettings& settings, const rhi::Conventions& conventions,
                                   std::span<const DirectionalShadowLightInput> lights,
                                   std::span<const SpotShadowInput> spots, std::span<const PointShadowInput> points,
                                   const StaticCasters& casters);

} // namespace penumbra::shadows
