// The shadow settings' table: each field of ShadowSettings declared once (path, range, allowed values, summary,
// option), from which validation, the settings file, the tool's options, the viewer's controls and docs/settings.md
// follow (penumbra/settings/SettingsTable.hpp).
#include "penumbra/shadows/ShadowSettings.hpp"

#include <fmt/format.h>
#include <iterator>
#include <string>
#include <vector>

namespace penumbra::shadows {
namespace {

using settings::nameOf;
using settings::SettingName;
using settings::SettingRange;
using settings::SettingRangeKind;

// The ranges several fields share, each stated once.
constexpr SettingRange kAtlasSizes{SettingRangeKind::PowersOfTwo, 256, 8192};
constexpr SettingRange kFraction{SettingRangeKind::Closed, 0.001, 1};
constexpr SettingRange kScale{SettingRangeKind::Closed, 0.1, 10};
constexpr SettingRange kPenumbraTexels{SettingRangeKind::Closed, 0, 64};
// Depth steps of a constant depth bias: up to the 500 000 of Catlike Coding's "Directional Shadows" (section 4.1).
constexpr SettingRange kDepthBias{SettingRangeKind::Closed, 0, 1000000};

std::vector<SettingName> filterNames()
{
    std::vector<SettingName> names;
    for (const ShadowFilterInfo& entry : shadowFilters())
        names.push_back(nameOf(entry.filter, entry.json));
    return names;
}

std::vector<SettingName> projectionSettingNames()
{
    std::vector<SettingName> names;
    for (const CascadeProjectionName& entry : cascadeProjectionNames())
        names.push_back(nameOf(entry.projection, entry.name));
    return names;
}

std::vector<SettingName> toggleNames() { return {nameOf(Toggle::Off, "off"), nameOf(Toggle::On, "on")}; }

std::vector<SettingName> depthFormats()
{
    return {nameOf(rhi::Format::D16, "d16"), nameOf(rhi::Format::D24S8, "d24s8"), nameOf(rhi::Format::D32F, "d32f")};
}

// The rules beyond the fields' ranges: each gives the refused value's text.
std::optional<std::string> cascadeRatiosIncrease(const ShadowSettings& s)
{
    const glm::vec3 r = s.directional.cascadeRatios;
    if (r.x < r.y && r.y < r.z)
        return std::nullopt;
    return fmt::format("[{}, {}, {}]", r.x, r.y, r.z);
}

std::optional<std::string> minTileWithinAtlas(const ShadowSettings& s)
{
    if (s.local.minTileResolution <= s.local.atlasSize)
        return std::nullopt;
    return fmt::format("{} (above local.atlasSize {})", s.local.minTileResolution, s.local.atlasSize);
}

// At least minPenumbraTexels: the field's range starts at the smallest minPenumbraTexels.
std::optional<std::string> maxPenumbraAtLeastMin(const ShadowSettings& s)
{
    if (s.soft.maxPenumbraTexels >= s.soft.minPenumbraTexels)
        return std::nullopt;
    return fmt::format("{}", s.soft.maxPenumbraTexels);
}

std::vector<ShadowSettingsField> shadowTableFields()
{
    const std::vector<double> sampleCounts(std::begin(kPoissonSampleCounts), std::end(kPoissonSampleCounts));
    const SettingRange poissonRadius{SettingRangeKind::Closed, 0.5, kPenumbraTexels.high};
    const SettingRange unit{SettingRangeKind::Closed, 0, 1};
    return {{
        settings::numeric<ShadowSettings>(
            "maxDistance", {SettingRangeKind::Above, 0.001},
            "view depth beyond which nothing is shadowed, for every light",
            [](auto& s) -> auto& { return s.maxDistance; }),
        settings::numeric<ShadowSettings>(
            "distanceFade", kFraction, "fraction of maxDistance over which shadows fade out",
            [](auto& s) -> auto& { return s.distanceFade; }),
        settings::named<ShadowSettings>(
            "culling", {nameOf(CasterCullingMode::Cpu, "cpu"), nameOf(CasterCullingMode::Gpu, "gpu")},
            "where the realtime atlases' casters are culled per tile: cpu (the planner) or gpu (a compute pass, "
            "indirect draws)",
            [](auto& s) -> auto& { return s.culling; }, "--culling"),
        settings::numeric<ShadowSettings>(
            "directional.atlasSize", kAtlasSizes, "texels per side of the directional atlas",
            [](auto& s) -> auto& { return s.directional.atlasSize; }),
        settings::named<ShadowSettings>(
            "directional.filter", filterNames(), "the directional lights' filter, unless a light sets its own",
            [](auto& s) -> auto& { return s.directional.filter; }),
        settings::numeric<ShadowSettings>(
            "directional.cascadeCount", {SettingRangeKind::Closed, 1, 4}, "cascades per directional light",
            [](auto& s) -> auto& { return s.directional.cascadeCount; }),
        settings::withRule(settings::field<ShadowSettings>(
                               "directional.cascadeRatios", unit,
                               fmt::format("3 numbers in {}, strictly increasing", settings::rangeText(unit)),
                               "ends of cascades 1..3 as fractions of maxDistance",
                               [](auto& s) -> auto& { return s.directional.cascadeRatios; }),
                           cascadeRatiosIncrease),
        settings::numeric<ShadowSettings>(
            "directional.cascadeFade", kFraction, "fraction of the last cascade over which it fades",
            [](auto& s) -> auto& { return s.directional.cascadeFade; }),
        settings::named<ShadowSettings>(
            "directional.cascadeBlend",
            {nameOf(CascadeBlend::Hard, "hard"), nameOf(CascadeBlend::Soft, "soft"),
             nameOf(CascadeBlend::Dither, "dither")},
            "how the lit pass moves from one cascade to the next",
            [](auto& s) -> auto& { return s.directional.cascadeBlend; }),
        settings::named<ShadowSettings>(
            "directional.projection", projectionSettingNames(),
            "stable: texel-snapped spheres that hold still; close: tiles fitted to the view's slices; depthFit: "
            "tiles fitted to the visible surfaces, split by their depths",
            [](auto& s) -> auto& { return s.directional.projection; }, "--projection"),
        settings::numeric<ShadowSettings>(
            "directional.depthFitSteps", {SettingRangeKind::Closed, 0, 64},
            "depthFit's grid steps per power of two of its tiles' size (0: unquantized)",
            [](auto& s) -> auto& { return s.directional.depthFitSteps; }),
        settings::numeric<ShadowSettings>(
            "directional.depthFitHysteresis", {SettingRangeKind::Closed, 0, 8},
            "grid steps a depthFit tile's fit must shrink inside its size before the tile does",
            [](auto& s) -> auto& { return s.directional.depthFitHysteresis; }),
        settings::named<ShadowSettings>(
            "directional.atlasFormat", depthFormats(), "depth format of the directional atlas",
            [](auto& s) -> auto& { return s.directional.atlasFormat; }),
        settings::numeric<ShadowSettings>(
            "directional.depthBias", kDepthBias,
            "constant depth bias of the directional casters, in depth steps, beside each light's slope-scaled one",
            [](auto& s) -> auto& { return s.directional.depthBias; }, "--directional-depth-bias"),
        settings::numeric<ShadowSettings>(
            "local.atlasSize", kAtlasSizes, "texels per side of the spot and point lights' atlas",
            [](auto& s) -> auto& { return s.local.atlasSize; }, "--local-atlas-size"),
        settings::named<ShadowSettings>(
            "local.filter", filterNames(), "the spot and point lights' filter, unless a light sets its own",
            [](auto& s) -> auto& { return s.local.filter; }),
        settings::named<ShadowSettings>(
            "local.atlasFormat", depthFormats(), "depth format of the local atlas",
            [](auto& s) -> auto& { return s.local.atlasFormat; }),
        settings::named<ShadowSettings>(
            "local.pointMode", {nameOf(PointShadowMode::Atlas, "atlas"), nameOf(PointShadowMode::CubeMap, "cubemap")},
            "point lights in six atlas tiles or in a depth cube map each",
            [](auto& s) -> auto& { return s.local.pointMode; }),
        settings::numeric<ShadowSettings>(
            "local.cubeMapSize", {SettingRangeKind::PowersOfTwo, 64, 4096}, "texels per face side in cubemap mode",
            [](auto& s) -> auto& { return s.local.cubeMapSize; }),
        settings::numeric<ShadowSettings>(
            "local.nearPlane", {SettingRangeKind::Closed, 0.0001, 0.5},
            "shadow near plane as a fraction of the light's range, for lights without one",
            [](auto& s) -> auto& { return s.local.nearPlane; }),
        settings::numeric<ShadowSettings>(
            "local.tileResolution", {SettingRangeKind::PowersOfTwo, 16, 8192},
            "texels per side a spot or point light without its own shadowResolution asks for when its reach fills "
            "the screen",
            [](auto& s) -> auto& { return s.local.tileResolution; }),
        settings::withRule(settings::numeric<ShadowSettings>(
                               "local.minTileResolution", {SettingRangeKind::PowersOfTwo, 16, 1024},
                               "texels per side a light's tile is lowered to, at most, before the light loses its "
                               "shadow",
                               [](auto& s) -> auto& { return s.local.minTileResolution; }),
                           minTileWithinAtlas),
        settings::numeric<ShadowSettings>(
            "local.depthBias", kDepthBias,
            "constant depth bias of the spot and point casters, in depth steps, beside each light's slope-scaled one",
            [](auto& s) -> auto& { return s.local.depthBias; }, "--local-depth-bias"),
        settings::named<ShadowSettings>(
            "local.spotFovBias", toggleNames(),
            "widens spot shadow frustums as point faces are, so bias and filter taps at the cone's edge stay in the "
            "tile",
            [](auto& s) -> auto& { return s.local.spotFovBias; }, "--spot-fov-bias"),
        settings::named<ShadowSettings>(
            "local.clusterBuild", {nameOf(LightClusterBuild::Cpu, "cpu"), nameOf(LightClusterBuild::Gpu, "gpu")},
            "where the lit pass's clustered light lists are built: cpu, or gpu (a compute pass; the same lists)",
            [](auto& s) -> auto& { return s.local.clusterBuild; }, "--cluster-build"),
        settings::numeric<ShadowSettings>(
            "soft.blockerSearchScale", kScale, "scales PCSS's blocker search region (NVIDIA's w_search)",
            [](auto& s) -> auto& { return s.soft.blockerSearchScale; }),
        settings::numeric<ShadowSettings>(
            "soft.penumbraScale", kScale, "scales PCSS's penumbra estimate (NVIDIA's w_penumbra)",
            [](auto& s) -> auto& { return s.soft.penumbraScale; }),
        settings::listed<ShadowSettings>(
            "soft.blockerSamples", sampleCounts, "Poisson disk taps of each blocker search",
            [](auto& s) -> auto& { return s.soft.blockerSamples; }),
        settings::listed<ShadowSettings>(
            "soft.filterSamples", sampleCounts, "Poisson disk taps of the soft filters",
            [](auto& s) -> auto& { return s.soft.filterSamples; }),
        settings::numeric<ShadowSettings>(
            "soft.minPenumbraTexels", kPenumbraTexels, "smallest filter radius of PCSS, in texels",
            [](auto& s) -> auto& { return s.soft.minPenumbraTexels; }),
        settings::withRule(settings::field<ShadowSettings>(
                               "soft.maxPenumbraTexels", kPenumbraTexels,
                               fmt::format("minPenumbraTexels..{}", kPenumbraTexels.high),
                               "largest filter radius and blocker search of PCSS, in texels",
                               [](auto& s) -> auto& { return s.soft.maxPenumbraTexels; }),
                           maxPenumbraAtLeastMin),
        settings::numeric<ShadowSettings>(
            "soft.poissonRadiusTexels", poissonRadius, "the fixed poisson filter's radius, in texels",
            [](auto& s) -> auto& { return s.soft.poissonRadiusTexels; }),
        settings::named<ShadowSettings>(
            "soft.diskRotation", toggleNames(),
            "turns the poisson and pcss disks per receiver texel (noise instead of the disk's fixed pattern)",
            [](auto& s) -> auto& { return s.soft.diskRotation; }, "--disk-rotation"),
        settings::named<ShadowSettings>(
            "static.update",
            {nameOf(StaticShadowUpdate::EveryFrame, "everyFrame"), nameOf(StaticShadowUpdate::OnChange, "onChange"),
             nameOf(StaticShadowUpdate::OnDemand, "onDemand")},
            "when static shadow maps are drawn; everyFrame keeps none",
            [](auto& s) -> auto& { return s.staticMaps.update; }, "--static-maps"),
        settings::named<ShadowSettings>(
            "static.realtimeCasters",
            {nameOf(RealtimeCasters::All, "all"), nameOf(RealtimeCasters::Dynamic, "dynamic")},
            "which casters the realtime atlases draw while static maps exist",
            [](auto& s) -> auto& { return s.staticMaps.realtimeCasters; }, "--realtime-casters"),
        settings::numeric<ShadowSettings>(
            "static.directionalAtlasSize", kAtlasSizes, "texels per side of the directional lights' static atlas",
            [](auto& s) -> auto& { return s.staticMaps.directionalAtlasSize; }),
        settings::numeric<ShadowSettings>(
            "static.localAtlasSize", kAtlasSizes, "texels per side of the spot and point lights' static atlas",
            [](auto& s) -> auto& { return s.staticMaps.localAtlasSize; }),
        settings::named<ShadowSettings>(
            "contact.shadows", toggleNames(),
            "a short screen-space march through the visible depths towards each directional light and the nearest spot and point lights, added to their shadow maps",
            [](auto& s) -> auto& { return s.contact.shadows; }, "--contact-shadows"),
        settings::numeric<ShadowSettings>(
            "contact.length", {SettingRangeKind::Closed, 0.01, 10}, "metres the contact march goes towards the light",
            [](auto& s) -> auto& { return s.contact.length; }),
        settings::numeric<ShadowSettings>(
            "contact.steps", {SettingRangeKind::Closed, 1, 64}, "depth samples along the contact march",
            [](auto& s) -> auto& { return s.contact.steps; }),
        settings::numeric<ShadowSettings>(
            "contact.thickness", {SettingRangeKind::Closed, 0.001, 10},
            "metres behind a depth sample that the contact march counts as inside its surface",
            [](auto& s) -> auto& { return s.contact.thickness; }),
        settings::numeric<ShadowSettings>(
            "contact.localLights", {SettingRangeKind::Closed, 0, static_cast<double>(kMaxContactLocalLights)},
            "spot and point lights with shadows that the contact march goes towards, the nearest the camera",
            [](auto& s) -> auto& { return s.contact.localLights; }, "--contact-local-lights"),
    }};
}

} // namespace

const settings::SettingsTable<ShadowSettings>& shadowSettingsTable()
{
    // Spot and point lights were once "other" lights: those paths still load.
    static const settings::SettingsTable<ShadowSettings> table(shadowTableFields(),
                                                               {{"other", "local"},
                                                                {"static.otherAtlasSize", "static.localAtlasSize"}});
    return table;
}

std::span<const ShadowSettingsField> shadowSettingsFields() { return shadowSettingsTable().fields(); }

const ShadowSettingsField& shadowSettingsField(std::string_view path) { return shadowSettingsTable().field(path); }

void validate(const ShadowSettings& settings) { shadowSettingsTable().validate(settings); }

} // namespace penumbra::shadows
