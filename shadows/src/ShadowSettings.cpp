#include "penumbra/shadows/ShadowSettings.hpp"

#include "ShadowSettingsCheck.hpp"
#include "penumbra/rhi/Error.hpp"

#include <array>
#include <string>
#include <fmt/format.h>
#include <utility>

namespace penumbra::shadows {

namespace {

// The Poisson filters' size is their centre tap's bilinear 2.
constexpr std::array<ShadowFilterInfo, kShadowFilterCount> kFilters{{
    {ShadowFilter::PCF2x2, "pcf2x2", "hard", 2, ShadowFilterFamily::Bilinear},
    {ShadowFilter::PCF3x3, "pcf3x3", "pcf3", 3, ShadowFilterFamily::Tent},
    {ShadowFilter::PCF5x5, "pcf5x5", "pcf5", 5, ShadowFilterFamily::Tent},
    {ShadowFilter::PCF7x7, "pcf7x7", "pcf7", 7, ShadowFilterFamily::Tent},
    {ShadowFilter::Poisson, "poisson", "poisson", 2, ShadowFilterFamily::PoissonDisk},
    {ShadowFilter::PCSS, "pcss", "pcss", 2, ShadowFilterFamily::PoissonDisk},
}};

// Each filter at its value's index, the families in order: the shaders tell them apart by comparing a filter with
// the first of a family (PENUMBRA_FILTER_FIRST_POISSON_DISK).
constexpr bool listedInOrder()
{
    for (std::size_t i = 0; i < kFilters.size(); ++i)
        if (static_cast<std::size_t>(kFilters[i].filter) != i || (i > 0 && kFilters[i - 1].family > kFilters[i].family))
            return false;
    return true;
}
static_assert(listedInOrder());

// One kind of the filters' names (JSON or command line), comma separated, in the table's order.
std::string filterNameList(std::string_view ShadowFilterInfo::*name)
{
    std::string text;
    for (const ShadowFilterInfo& entry : kFilters)
        text += fmt::format("{}{}", text.empty() ? "" : ", ", entry.*name);
    return text;
}

} // namespace

const std::array<ShadowFilterInfo, kShadowFilterCount>& shadowFilters() { return kFilters; }

std::span<const ShadowSettingsField> shadowSettingsFields()
{
    static const std::string filterNames = filterNameList(&ShadowFilterInfo::json);
    static const std::array<ShadowSettingsField, 27> fields{{
        {"maxDistance", "> 0.001", "view depth beyond which nothing is shadowed, for every light"},
        {"distanceFade", "0.001..1", "fraction of maxDistance over which shadows fade out"},
        {"directional.atlasSize", "powers of two 256..8192", "texels per side of the directional atlas"},
        {"directional.filter", filterNames, "the directional lights' filter, unless a light sets its own"},
        {"directional.cascadeCount", "1..4", "cascades per directional light"},
        {"directional.cascadeRatios", "3 numbers in 0..1, strictly increasing",
         "ends of cascades 1..3 as fractions of maxDistance"},
        {"directional.cascadeFade", "0.001..1", "fraction of the last cascade over which it fades"},
        {"directional.cascadeBlend", "hard, soft, dither", "how the lit pass moves from one cascade to the next"},
        {"directional.projection", "stable, close",
         "stable: texel-snapped spheres that hold still; close: tiles fitted to the view's slices"},
        {"directional.atlasFormat", "d16, d24s8, d32f", "depth format of the directional atlas"},
        {"local.atlasSize", "powers of two 256..8192", "texels per side of the spot and point lights' atlas"},
        {"local.filter", filterNames, "the spot and point lights' filter, unless a light sets its own"},
        {"local.atlasFormat", "d16, d24s8, d32f", "depth format of the local atlas"},
        {"local.pointMode", "atlas, cubemap", "point lights in six atlas tiles or in a depth cube map each"},
        {"local.cubeMapSize", "powers of two 64..4096", "texels per face side in cubemap mode"},
        {"local.nearPlane", "0.0001..0.5",
         "shadow near plane as a fraction of the light's range, for lights without one"},
        {"soft.blockerSearchScale", "0.1..10", "scales PCSS's blocker search region (NVIDIA's w_search)"},
        {"soft.penumbraScale", "0.1..10", "scales PCSS's penumbra estimate (NVIDIA's w_penumbra)"},
        {"soft.blockerSamples", "16, 32, 64", "Poisson disk taps of each blocker search"},
        {"soft.filterSamples", "16, 32, 64", "Poisson disk taps of the soft filters"},
        {"soft.minPenumbraTexels", "0..64", "smallest filter radius of PCSS, in texels"},
        {"soft.maxPenumbraTexels", "minPenumbraTexels..64",
         "largest filter radius and blocker search of PCSS, in texels"},
        {"soft.poissonRadiusTexels", "0.5..64", "the fixed poisson filter's radius, in texels"},
        {"static.update", "everyFrame, onChange, onDemand", "when static shadow maps are drawn; everyFrame keeps none"},
        {"static.realtimeCasters", "all, dynamic", "which casters the realtime atlases draw while static maps exist"},
        {"static.directionalAtlasSize", "powers of two 256..8192",
         "texels per side of the directional lights' static atlas"},
        {"static.localAtlasSize", "powers of two 256..8192",
         "texels per side of the spot and point lights' static atlas"},
    }};
    return fields;
}

std::optional<ShadowFilter> filterFromCommandName(std::string_view name)
{
    for (const ShadowFilterInfo& entry : shadowFilters())
        if (entry.command == name)
            return entry.filter;
    return std::nullopt;
}

std::string_view filterCommandNames()
{
    static const std::string names = filterNameList(&ShadowFilterInfo::command);
    return names;
}

const std::array<CascadeProjectionName, kCascadeProjectionCount>& cascadeProjectionNames()
{
    static constexpr std::array<CascadeProjectionName, kCascadeProjectionCount> names{{
        {CascadeProjection::Stable, "stable"},
        {CascadeProjection::Close, "close"},
    }};
    return names;
}

std::optional<CascadeProjection> projectionFromName(std::string_view name)
{
    for (const CascadeProjectionName& entry : cascadeProjectionNames())
        if (entry.name == name)
            return entry.projection;
    return std::nullopt;
}

std::string_view projectionNames() { return "stable, close"; }

ShadowFilterFamily filterFamily(ShadowFilter filter)
{
    return shadowFilters()[static_cast<std::size_t>(filter)].family;
}

bool isSoftFilter(ShadowFilter filter) { return filterFamily(filter) == ShadowFilterFamily::PoissonDisk; }

int filterSize(ShadowFilter filter) { return shadowFilters()[static_cast<std::size_t>(filter)].size; }

float normalBiasFilterFactor(ShadowFilter filter)
{
    return isSoftFilter(filter) ? 1.0f : static_cast<float>((filterSize(filter) + 1) / 2);
}

int filterTapCount(ShadowFilter filter)
{
    // An N-wide tent touches N + 1 texels per axis (N odd), read in pairs by bilinear taps.
    const int perAxis = filterFamily(filter) == ShadowFilterFamily::Tent ? (filterSize(filter) + 1) / 2 : 1;
    return perAxis * perAxis;
}

void validate(const ShadowSettings& settings)
{
    if (const auto problem = detail::findSettingsProblem(settings))
        throw rhi::Error(fmt::format("{}: {}, allowed {}", problem->field, problem->what, problem->allowed));
}

namespace detail {
namespace {

// NaN compares false, so it is never within a range.
bool within(float value, float low, float high) { return value >= low && value <= high; }

SettingsProblem outOfRange(std::string field, std::string value)
{
    std::string allowed(allowedValues(field));
    return {std::move(field), value + " is out of range", std::move(allowed)};
}

} // namespace

std::string_view allowedValues(std::string_view field)
{
    for (const ShadowSettingsField& entry : shadowSettingsFields())
        if (entry.path == field)
            return entry.allowed;
    return "";
}

namespace {

bool powerOfTwoWithin(std::uint32_t value, std::uint32_t low, std::uint32_t high)
{
    return (value & (value - 1)) == 0 && value >= low && value <= high;
}

std::optional<SettingsProblem> findLocalSettingsProblem(const LocalShadowSettings& o)
{
    if (!powerOfTwoWithin(o.atlasSize, 256, 8192))
        return outOfRange("local.atlasSize", fmt::format("{}", o.atlasSize));
    if (static_cast<unsigned>(o.filter) > static_cast<unsigned>(ShadowFilter::PCSS))
        return outOfRange("local.filter", fmt::format("{}", static_cast<int>(o.filter)));
    if (!rhi::isDepthFormat(o.atlasFormat))
        return outOfRange("local.atlasFormat", std::string(rhi::formatName(o.atlasFormat)));
    if (static_cast<unsigned>(o.pointMode) > static_cast<unsigned>(PointShadowMode::CubeMap))
        return outOfRange("local.pointMode", fmt::format("{}", static_cast<int>(o.pointMode)));
    if (!powerOfTwoWithin(o.cubeMapSize, 64, 4096))
        return outOfRange("local.cubeMapSize", fmt::format("{}", o.cubeMapSize));
    if (!within(o.nearPlane, 0.0001f, 0.5f))
        return outOfRange("local.nearPlane", fmt::format("{}", o.nearPlane));
    return std::nullopt;
}

bool isPoissonSampleCount(std::uint32_t count)
{
    for (const std::uint32_t offered : kPoissonSampleCounts)
        if (count == offered)
            return true;
    return false;
}

std::optional<SettingsProblem> findSoftSettingsProblem(const SoftShadowSettings& s)
{
    if (!within(s.blockerSearchScale, 0.1f, 10.0f))
        return outOfRange("soft.blockerSearchScale", fmt::format("{}", s.blockerSearchScale));
    if (!within(s.penumbraScale, 0.1f, 10.0f))
        return outOfRange("soft.penumbraScale", fmt::format("{}", s.penumbraScale));
    if (!isPoissonSampleCount(s.blockerSamples))
        return outOfRange("soft.blockerSamples", fmt::format("{}", s.blockerSamples));
    if (!isPoissonSampleCount(s.filterSamples))
        return outOfRange("soft.filterSamples", fmt::format("{}", s.filterSamples));
    if (!within(s.minPenumbraTexels, 0.0f, 64.0f))
        return outOfRange("soft.minPenumbraTexels", fmt::format("{}", s.minPenumbraTexels));
    if (!within(s.maxPenumbraTexels, s.minPenumbraTexels, 64.0f))
        return outOfRange("soft.maxPenumbraTexels", fmt::format("{}", s.maxPenumbraTexels));
    if (!within(s.poissonRadiusTexels, 0.5f, 64.0f))
        return outOfRange("soft.poissonRadiusTexels", fmt::format("{}", s.poissonRadiusTexels));
    return std::nullopt;
}

std::optional<SettingsProblem> findStaticSettingsProblem(const StaticShadowSettings& s)
{
    if (static_cast<unsigned>(s.update) > static_cast<unsigned>(StaticShadowUpdate::OnDemand))
        return outOfRange("static.update", fmt::format("{}", static_cast<int>(s.update)));
    if (static_cast<unsigned>(s.realtimeCasters) > static_cast<unsigned>(RealtimeCasters::Dynamic))
        return outOfRange("static.realtimeCasters", fmt::format("{}", static_cast<int>(s.realtimeCasters)));
    if (!powerOfTwoWithin(s.directionalAtlasSize, 256, 8192))
        return outOfRange("static.directionalAtlasSize", fmt::format("{}", s.directionalAtlasSize));
    if (!powerOfTwoWithin(s.localAtlasSize, 256, 8192))
        return outOfRange("static.localAtlasSize", fmt::format("{}", s.localAtlasSize));
    return std::nullopt;
}

} // namespace

std::optional<SettingsProblem> findSettingsProblem(const ShadowSettings& s)
{
    const DirectionalShadowSettings& d = s.directional;
    if (!(s.maxDistance > 0.001f))
        return outOfRange("maxDistance", fmt::format("{}", s.maxDistance));
    if (!within(s.distanceFade, 0.001f, 1.0f))
        return outOfRange("distanceFade", fmt::format("{}", s.distanceFade));
    if (!powerOfTwoWithin(d.atlasSize, 256, 8192))
        return outOfRange("directional.atlasSize", fmt::format("{}", d.atlasSize));
    if (static_cast<unsigned>(d.filter) > static_cast<unsigned>(ShadowFilter::PCSS))
        return outOfRange("directional.filter", fmt::format("{}", static_cast<int>(d.filter)));
    if (d.cascadeCount < 1 || d.cascadeCount > 4)
        return outOfRange("directional.cascadeCount", fmt::format("{}", d.cascadeCount));
    const glm::vec3 r = d.cascadeRatios;
    if (!within(r.x, 0.0f, 1.0f) || !within(r.y, 0.0f, 1.0f) || !within(r.z, 0.0f, 1.0f) || !(r.x < r.y) ||
        !(r.y < r.z))
        return outOfRange("directional.cascadeRatios", fmt::format("[{}, {}, {}]", r.x, r.y, r.z));
    if (!within(d.cascadeFade, 0.001f, 1.0f))
        return outOfRange("directional.cascadeFade", fmt::format("{}", d.cascadeFade));
    if (static_cast<unsigned>(d.cascadeBlend) > static_cast<unsigned>(CascadeBlend::Dither))
        return outOfRange("directional.cascadeBlend", fmt::format("{}", static_cast<int>(d.cascadeBlend)));
    if (static_cast<unsigned>(d.projection) >= static_cast<unsigned>(kCascadeProjectionCount))
        return outOfRange("directional.projection", fmt::format("{}", static_cast<int>(d.projection)));
    if (!rhi::isDepthFormat(d.atlasFormat))
        return outOfRange("directional.atlasFormat", std::string(rhi::formatName(d.atlasFormat)));
    if (auto problem = findLocalSettingsProblem(s.local))
        return problem;
    if (auto problem = findSoftSettingsProblem(s.soft))
        return problem;
    return findStaticSettingsProblem(s.staticMaps);
}

} // namespace detail
} // namespace penumbra::shadows
