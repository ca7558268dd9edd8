#pragma once

#include "penumbra/rhi/Format.hpp"
#include "penumbra/settings/SettingsTable.hpp"
#include "penumbra/shadows/LightVocabulary.hpp"

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::shadows {

// How the lit shader filters the atlas: one bilinear comparison, a tent of bilinear comparisons, or a Poisson disk
// (with PCSS's blocker search or without). The enum lists the families in this order.
enum class ShadowFilterFamily { Bilinear, Tent, PoissonDisk };

// Everything about one filter, in one table (shadowFilters()): its names in the settings JSON ("pcf2x2".."pcf7x7",
// "poisson", "pcss") and on the command line ("hard", "pcf3", "pcf5", "pcf7", "poisson", "pcss"), its kernel width
// in texels and its family. The names, the validation messages, the viewer's list and the shader constants follow it.
struct ShadowFilterInfo {
    ShadowFilter filter;
    std::string_view json;
    std::string_view command;
    int size;
    ShadowFilterFamily family;
};
const std::array<ShadowFilterInfo, kShadowFilterCount>& shadowFilters();
std::optional<ShadowFilter> filterFromCommandName(std::string_view name);
// "hard, pcf3, pcf5, pcf7, poisson, pcss".
std::string_view filterCommandNames();

ShadowFilterFamily filterFamily(ShadowFilter filter);
// Whether the filter is one of the Poisson-disk filters (Poisson, PCSS), which take SoftShadowSettings.
bool isSoftFilter(ShadowFilter filter);

// A setting that is either off or on ("off", "on" in the settings file, on the command line and in the viewer).
enum class Toggle { Off, On };

// How the lit shader moves from one cascade to the next.
enum class CascadeBlend { Hard, Soft, Dither };

// Unity's "Shadow Projection" quality setting (Catlike Coding, "Rendering 7: Shadows", section 1.7 "Shadow
// Quality"). Stable fit: cascades are bands of distance to the camera, each tile a texel-snapped square around the
// slice's bounding sphere, so the shadow texels stay put while the camera moves or turns. Close fit: cascades are
// bands of the camera's view depth, each tile fitted to the light-space bounds of its frustum slice: more texels on
// screen, but the tiles change size as the camera turns and the shadow edges swim. Depth fit: bands of view depth
// split where the last frame's visible depths put the most texels on them, each tile fitted to the light-space
// footprint of the surfaces seen in its band (a histogram reduced from the depth prepass: shadows/DepthFit.hpp), the
// tile sizes on a grid with hysteresis so the texels hold still while the footprints barely change; the close fit
// until a frame has been reduced. The values are the lit shader's (generated into shadow_constants.glsl as
// PENUMBRA_PROJECTION_<NAME>).
enum class CascadeProjection { Stable, Close, DepthFit };
inline constexpr int kCascadeProjectionCount = 3;

// The projection's names, in the settings JSON and on the command line alike: "stable", "close", "depthFit".
struct CascadeProjectionName {
    CascadeProjection projection;
    std::string_view name;
};
const std::array<CascadeProjectionName, kCascadeProjectionCount>& cascadeProjectionNames();
std::optional<CascadeProjection> projectionFromName(std::string_view name);
// "stable, close, depthFit".
std::string_view projectionNames();

// Width of a tent filter's kernel in texels: 2, 3, 5, 7 (the Poisson filters: 2, their centre tap's bilinear).
int filterSize(ShadowFilter filter);

// The "filter size" of Catlike Coding's "Directional Shadows" tutorial (section "Shadow Quality")
// for the normal bias and the culling-sphere shrink:
// enum + 1 = 1, 2, 3, 4 texels (texel size x this x sqrt 2 is the normal bias), not the kernel width. The Poisson
// filters take 1, as the 2x2 does: their receiver-plane depth bias (soft_shadows.glsl) covers the wider kernel.
float normalBiasFilterFactor(ShadowFilter filter);

// Bilinear comparison taps the tent filters take: 1, 4, 9, 16 (the Poisson filters: SoftShadowSettings's counts).
int filterTapCount(ShadowFilter filter);

// The Poisson disk sizes offered for blocker searches and filters.
inline constexpr std::uint32_t kPoissonSampleCounts[] = {16, 32, 64};

// The PCSS controls (after NVIDIA's "Integrating Realistic Soft Shadows into Your Game Engine", 2008):
// its s_search and s_penumbra as scales of the light-size terms, the Poisson sample counts and the penumbra's
// clamp. Shared by every light whose filter is Poisson or PCSS.
struct SoftShadowSettings {
    float blockerSearchScale = 1.0f; // scales w_search
    float penumbraScale = 1.0f; // scales w_penumbra
    std::uint32_t blockerSamples = 16; // one of kPoissonSampleCounts
    std::uint32_t filterSamples = 16; // one of kPoissonSampleCounts
    float minPenumbraTexels = 1.0f; // the filter radius never goes below this
    float maxPenumbraTexels = 24.0f; // at least minPenumbraTexels; nor above this (nor the blocker search)
    float poissonRadiusTexels = 2.5f; // the fixed-radius Poisson filter's radius
    // Whether each receiver turns the disk by a hash of its texel in the light's grid (the rotation of the design
    // document on PCSS, there from a blue-noise texture): on, the disk's fixed pattern becomes noise; off, every
    // receiver reads the same disk.
    Toggle diskRotation = Toggle::On;
};

// The directional lights' atlas, filter and cascades. The allowed values of every settings field are stated once,
// in shadowSettingsFields() (docs/settings.md lists them).
struct DirectionalShadowSettings {
    std::uint32_t atlasSize = 1024; // texels per side
    ShadowFilter filter = ShadowFilter::PCF2x2;
    std::uint32_t cascadeCount = 4;
    glm::vec3 cascadeRatios{0.1f, 0.25f, 0.5f}; // ends of cascades 1..3 as fractions of the shadow distance
    float cascadeFade = 0.1f; // fraction of the last cascade's radius that fades
    CascadeBlend cascadeBlend = CascadeBlend::Hard;
    CascadeProjection projection = CascadeProjection::Stable;
    // Depth fit: grid steps per power of two of light-space size for the tiles' half sizes (0: unquantized, as the
    // footprints need, which swims), and how many steps further below the kept size a tile's need must fall before
    // the tile shrinks; hysteresis / steps is also the log2 of the texel size a kept partition may lose against the
    // best before it is dropped. A tile but the last also keeps its size while its footprint grows by up to half a
    // step (DepthFit.hpp).
    std::uint32_t depthFitSteps = 8;
    float depthFitHysteresis = 1.0f;
    rhi::Format atlasFormat = rhi::Format::D32F;
    // The rasteriser's constant depth bias of the casters, beside each light's slope-scaled one (the first argument
    // of Unity's SetGlobalDepthBias in Catlike Coding's "Directional Shadows", section 4.1): in units of the atlas
    // format's smallest depth step. 0 keeps the normal and slope-scaled biases alone.
    float depthBias = 0.0f;
};

// Where point lights keep their six faces.
enum class PointShadowMode {
    Atlas, // six tiles of the local atlas, the face picked in the lit shader (Catlike Coding's "Point and Spot
           // Shadows")
    CubeMap, // a depth cube map per light, sampled with hardware cube lookups
};

// Where the lit pass's clustered light lists are built (LightClusters.hpp): by buildLightClusters on the CPU (the
// reference), or by a compute pass into the same textures (GpuLightClusters, docs/many-lights.md).
enum class LightClusterBuild { Cpu, Gpu };

// Spot and point shadows: the second atlas of up to 16 tiles (a spot light takes one, a point light six).
struct LocalShadowSettings {
    std::uint32_t atlasSize = 1024; // texels per side
    ShadowFilter filter = ShadowFilter::PCF2x2;
    rhi::Format atlasFormat = rhi::Format::D32F;
    PointShadowMode pointMode = PointShadowMode::Atlas;
    std::uint32_t cubeMapSize = 512; // CubeMap mode: texels per face side
    // Near plane of a spot or point shadow projection as a fraction of the light's range, for lights that set none: 1%
    // keeps 32-bit and 24-bit depth resolution at the far end, while casters nearer than that to the light are rare.
    float nearPlane = 0.01f;
    // Each spot light's tile and point light's faces are sized on their own (ShadowAtlasPacker): the light's
    // shadowResolution, or this without one, times its importance on screen (localShadowRequest); texels per side.
    std::uint32_t tileResolution = 1024;
    // The least a tile is lowered to when the atlas runs out of room, before a light loses its shadow.
    std::uint32_t minTileResolution = 64;
    // The constant depth bias of the spot and point casters (DirectionalShadowSettings::depthBias).
    float depthBias = 0.0f;
    // Widens each spot light's shadow frustum as the point faces' are, so that the normal bias and the filter's taps
    // at the cone's edge stay inside its tile (Catlike Coding, "Point and Spot Shadows", section 2.5 "Field of View
    // Bias", applied to spot lights as the tutorial suggests): the tile then spends a few texels outside the cone.
    Toggle spotFovBias = Toggle::Off;
    LightClusterBuild clusterBuild = LightClusterBuild::Cpu;
};

// Which casters the realtime atlases draw while static maps exist.
enum class RealtimeCasters {
    All, // every caster; the static map adds the shadow beyond the shadow distance and for lights without tiles
    Dynamic, // dynamic casters only; the static casters' shadow comes from the static map (Unity's Shadowmask mode)
};

// Static shadow maps: per shadowed light, the static casters' depth kept between frames, or loaded from a bake.
struct StaticShadowSettings {
    StaticShadowUpdate update = StaticShadowUpdate::EveryFrame;
    RealtimeCasters realtimeCasters = RealtimeCasters::All;
    // Directional lights: one orthographic map each over the static casters' bounds, tiles of this atlas
    // (one light takes it whole, up to four share it as quarters); texels per side.
    std::uint32_t directionalAtlasSize = 4096;
    // Spot and point lights: tiles of this atlas as in the local atlas (a spot light one, a point light six, up to
    // 16); texels per side.
    std::uint32_t localAtlasSize = 2048;
};

// The most spot and point lights a frame marches contact shadows towards (ContactShadowSettings::localLights): a
// bit each in the contact shadow texture.
inline constexpr std::uint32_t kMaxContactLocalLights = 4;

// Contact shadows: a short march through the camera's depth buffer from each shaded pixel towards each shadowed
// directional light and the `localLights` nearest shadowed spot and point lights (nearestContactLights), whose hit
// darkens the light's direct term (the minimum with the map's visibility) where the map's texels and biases leave a
// gap under small casters and at contacts (Bend Studio, "Bend Studio's screen space shadows", SIGGRAPH 2023; Unreal
// Engine's "Contact Shadows" documentation).
struct ContactShadowSettings {
    Toggle shadows = Toggle::Off;
    float length = 0.3f; // metres of the march towards the light
    std::uint32_t steps = 12; // depth samples along it
    // Metres behind a depth sample that still count as inside its surface. Thin: a march that passes behind a caster
    // thinner than the band in view (a leaf, a slat) counts it without meeting it (Unity HDRP's Contact Shadows
    // "Thickness" likewise defaults low); docs/shadows-contact.md gives the ray cast's figures.
    float thickness = 0.05f;
    std::uint32_t localLights = 1; // spot and point lights marched towards, 0 to kMaxContactLocalLights
};

// Where the realtime atlases' casters are culled per tile: by the planner on the CPU (the reference and the
// fallback), or by a compute pass that writes each tile's instance lists and indirect draws (docs/compute.md).
enum class CasterCullingMode { Cpu, Gpu };

// Every shadow setting of a frame; docs/settings.md lists each field with its default and range.
struct ShadowSettings {
    float maxDistance = 100.0f; // view depth beyond which nothing is shadowed; applies to every light
    float distanceFade = 0.1f; // fraction of maxDistance over which shadows fade out
    CasterCullingMode culling = CasterCullingMode::Cpu;
    DirectionalShadowSettings directional;
    LocalShadowSettings local;
    SoftShadowSettings soft;
    StaticShadowSettings staticMaps;
    ContactShadowSettings contact;
};

// Whether the settings keep static shadow maps (any update mode but EveryFrame).
inline bool hasStaticMaps(const ShadowSettings& settings)
{
    return settings.staticMaps.update != StaticShadowUpdate::EveryFrame;
}

// Whether the realtime atlas tiles' casters are culled on the GPU: asked for, and every caster drawn (with
// RealtimeCasters::Dynamic the tiles' lists are split between the static and the realtime atlases on the CPU).
inline bool culledOnGpu(const ShadowSettings& settings)
{
    return settings.culling == CasterCullingMode::Gpu && settings.staticMaps.realtimeCasters == RealtimeCasters::All;
}

// Each field of ShadowSettings declared once (ShadowSettingsTable.cpp): its path in the JSON
// ("directional.cascadeCount"; the "static" object is ShadowSettings::staticMaps), its range, the values it allows as
// messages, help and docs state them, what it does in a line, and the option of the penumbra tool that sets it over a
// settings file ("--projection"; empty for none); its default is ShadowSettings{}'s. The fields are in the settings
// file's order; validate(), the settings file (ShadowSettingsJson.hpp), the settings reference (`penumbra settings
// --markdown`, docs/settings.md), the tool's options and the viewer's controls take their ranges and words from it.
using ShadowSettingsField = settings::SettingsField<ShadowSettings>;
const settings::SettingsTable<ShadowSettings>& shadowSettingsTable();
std::span<const ShadowSettingsField> shadowSettingsFields();
// The field of that path; throws rhi::Error naming the path where no field has it.
const ShadowSettingsField& shadowSettingsField(std::string_view path);

// Throws rhi::Error "<field>: <value> is out of range, allowed <range>" for the first field out of range
// (field paths as in JSON: "directional.cascadeCount").
void validate(const ShadowSettings& settings);

} // namespace penumbra::shadows
