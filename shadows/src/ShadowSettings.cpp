#include "penumbra/shadows/ShadowSettings.hpp"

#include "ShadowSettingsCheck.hpp"
#include "penumbra/rhi/Error.hpp"

#include <array>
#include <string>
#include <fmt/format.h>
#include <fmt/ranges.h>
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

// The ranges several fields share, each stated once.
constexpr SettingRange kAtlasSizes{SettingRangeKind::PowersOfTwo, 256, 8192};
constexpr SettingRange kFraction{SettingRangeKind::Closed, 0.001, 1};
constexpr SettingRange kScale{SettingRangeKind::Closed, 0.1, 10};
constexpr SettingRange kPenumbraTexels{SettingRangeKind::Closed, 0, 64};

// A numeric range as messages, help and docs state it: "0.001..1", "powers of two 256..8192", "> 0.001".
std::string rangeText(const SettingRange& range)
{
    switch (range.kind) {
    case SettingRangeKind::Closed:
        return fmt::format("{}..{}", range.low, range.high);
    case SettingRangeKind::PowersOfTwo:
        return fmt::format("powers of two {}..{}", range.low, range.high);
    case SettingRangeKind::Above:
        return fmt::format("> {}", range.low);
    case SettingRangeKind::Listed:
        break;
    }
    return "";
}

ShadowSettingsField numeric(std::string_view path, SettingRange range, std::string_view summary)
{
    return {path, range, rangeText(range), summary, {}};
}

ShadowSettingsField listed(std::string_view path, std::string names, std::string_view summary,
                           std::string_view flag = {})
{
    return {path, {}, std::move(names), summary, flag};
}

std::array<ShadowSettingsField, 27> makeFields()
{
    const std::string filterNames = filterNameList(&ShadowFilterInfo::json);
    const std::string sampleCounts = fmt::format("{}", fmt::join(kPoissonSampleCounts, ", "));
    const SettingRange poissonRadius{SettingRangeKind::Closed, 0.5, kPenumbraTexels.high};
    const SettingRange unit{SettingRangeKind::Closed, 0, 1};
    return {{
        numeric("maxDistance", {SettingRangeKind::Above, 0.001},
                "view depth beyond which nothing is shadowed, for every light"),
        numeric("distanceFade", kFraction, "fraction of maxDistance over which shadows fade out"),
        numeric("directional.atlasSize", kAtlasSizes, "texels per side of the directional atlas"),
        listed("directional.filter", filterNames, "the directional lights' filter, unless a light sets its own"),
        numeric("directional.cascadeCount", {SettingRangeKind::Closed, 1, 4}, "cascades per directional light"),
        {"directional.cascadeRatios",
         unit,
         fmt::format("3 numbers in {}, strictly increasing", rangeText(unit)),
         "ends of cascades 1..3 as fractions of maxDistance",
         {}},
        numeric("directional.cascadeFade", kFraction, "fraction of the last cascade over which it fades"),
        listed("directional.cascadeBlend", "hard, soft, dither", "how the lit pass moves from one cascade to the next"),
        listed("directional.projection", std::string(projectionNames()),
               "stable: texel-snapped spheres that hold still; close: tiles fitted to the view's slices",
               "--projection"),
        listed("directional.atlasFormat", "d16, d24s8, d32f", "depth format of the directional atlas"),
        numeric("local.atlasSize", kAtlasSizes, "texels per side of the spot and point lights' atlas"),
        listed("local.filter", filterNames, "the spot and point lights' filter, unless a light sets its own"),
        listed("local.atlasFormat", "d16, d24s8, d32f", "depth format of the local atlas"),
        listed("local.pointMode", "atlas, cubemap", "point lights in six atlas tiles or in a depth cube map each"),
        numeric("local.cubeMapSize", {SettingRangeKind::PowersOfTwo, 64, 4096}, "texels per face side in cubemap mode"),
        numeric("local.nearPlane", {SettingRangeKind::Closed, 0.0001, 0.5},
                "shadow near plane as a fraction of the light's range, for lights without one"),
        numeric("soft.blockerSearchScale", kScale, "scales PCSS's blocker search region (NVIDIA's w_search)"),
        numeric("soft.penumbraScale", kScale, "scales PCSS's penumbra estimate (NVIDIA's w_penumbra)"),
        listed("soft.blockerSamples", sampleCounts, "Poisson disk taps of each blocker search"),
        listed("soft.filterSamples", sampleCounts, "Poisson disk taps of the soft filters"),
        numeric("soft.minPenumbraTexels", kPenumbraTexels, "smallest filter radius of PCSS, in texels"),
        {"soft.maxPenumbraTexels",
         kPenumbraTexels,
         fmt::format("minPenumbraTexels..{}", kPenumbraTexels.high),
         "largest filter radius and blocker search of PCSS, in texels",
         {}},
        numeric("soft.poissonRadiusTexels", poissonRadius, "the fixed poisson filter's radius, in texels"),
        listed("static.update", "everyFrame, onChange, onDemand",
               "when static shadow maps are drawn; everyFrame keeps none", "--static-maps"),
        listed("static.realtimeCasters", "all, dynamic",
               "which casters the realtime atlases draw while static maps exist", "--realtime-casters"),
        numeric("static.directionalAtlasSize", kAtlasSizes, "texels per side of the directional lights' static atlas"),
        numeric("static.localAtlasSize", kAtlasSizes, "texels per side of the spot and point lights' static atlas"),
    }};
}

} // namespace

const std::array<ShadowFilterInfo, kShadowFilterCount>& shadowFilters() { return kFilters; }

bool withinRange(const SettingRange& range, double value)
{
    // As floats: a float field at a bound (0.0001f) is within it, as its float check always had it.
    const float v = static_cast<float>(value);
    switch (range.kind) {
    case SettingRangeKind::Listed:
        return true;
    case SettingRangeKind::Closed:
        return v >= static_cast<float>(range.low) && v <= static_cast<float>(range.high);
    case SettingRangeKind::Above:
        return v > static_cast<float>(range.low);
    case SettingRangeKind::PowersOfTwo: {
        if (!(value >= range.low && value <= range.high))
            return false;
        const auto whole = static_cast<std::uint64_t>(value);
        return static_cast<double>(whole) == value && (whole & (whole - 1)) == 0;
    }
    }
    return false;
}

const ShadowSettingsField& shadowSettingsField(std::string_view path)
{
    for (const ShadowSettingsField& field : shadowSettingsFields())
        if (field.path == path)
            return field;
    throw rhi::Error(fmt::format("{}: no shadow settings field has this path", path));
}

std::span<const ShadowSettingsField> shadowSettingsFields()
{
    static const std::array<ShadowSettingsField, 27> fields = makeFields();
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

SettingsProblem outOfRange(std::string field, std::string value)
{
    std::string allowed(allowedValues(field));
    return {std::move(field), value + " is out of range", std::move(allowed)};
}

// A numeric field against its range in the table.
template <typename Value>
std::optional<SettingsProblem> outsideRange(std::string_view path, Value value)
{
    if (withinRange(shadowSettingsField(path).range, static_cast<double>(value)))
        return std::nullopt;
    return outOfRange(std::string(path), fmt::format("{}", value));
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

std::optional<SettingsProblem> findLocalSettingsProblem(const LocalShadowSettings& o)
{
    if (auto problem = outsideRange("local.atlasSize", o.atlasSize))
        return problem;
    if (static_cast<unsigned>(o.filter) > static_cast<unsigned>(ShadowFilter::PCSS))
        return outOfRange("local.filter", fmt::format("{}", static_cast<int>(o.filter)));
    if (!rhi::isDepthFormat(o.atlasFormat))
        return outOfRange("local.atlasFormat", std::string(rhi::formatName(o.atlasFormat)));
    if (static_cast<unsigned>(o.pointMode) > static_cast<unsigned>(PointShadowMode::CubeMap))
        return outOfRange("local.pointMode", fmt::format("{}", static_cast<int>(o.pointMode)));
    if (auto problem = outsideRange("local.cubeMapSize", o.cubeMapSize))
        return problem;
    if (auto problem = outsideRange("local.nearPlane", o.nearPlane))
        return problem;
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
    if (auto problem = outsideRange("soft.blockerSearchScale", s.blockerSearchScale))
        return problem;
    if (auto problem = outsideRange("soft.penumbraScale", s.penumbraScale))
        return problem;
    if (!isPoissonSampleCount(s.blockerSamples))
        return outOfRange("soft.blockerSamples", fmt::format("{}", s.blockerSamples));
    if (!isPoissonSampleCount(s.filterSamples))
        return outOfRange("soft.filterSamples", fmt::format("{}", s.filterSamples));
    if (auto problem = outsideRange("soft.minPenumbraTexels", s.minPenumbraTexels))
        return problem;
    // At least minPenumbraTexels: the table's low bound is the smallest minPenumbraTexels.
    const SettingRange maxPenumbra = shadowSettingsField("soft.maxPenumbraTexels").range;
    if (!withinRange({SettingRangeKind::Closed, s.minPenumbraTexels, maxPenumbra.high}, s.maxPenumbraTexels))
        return outOfRange("soft.maxPenumbraTexels", fmt::format("{}", s.maxPenumbraTexels));
    if (auto problem = outsideRange("soft.poissonRadiusTexels", s.poissonRadiusTexels))
        return problem;
    return std::nullopt;
}

std::optional<SettingsProblem> findStaticSettingsProblem(const StaticShadowSettings& s)
{
    if (static_cast<unsigned>(s.update) > static_cast<unsigned>(StaticShadowUpdate::OnDemand))
        return outOfRange("static.update", fmt::format("{}", static_cast<int>(s.update)));
    if (static_cast<unsigned>(s.realtimeCasters) > static_cast<unsigned>(RealtimeCasters::Dynamic))
        return outOfRange("static.realtimeCasters", fmt::format("{}", static_cast<int>(s.realtimeCasters)));
    if (auto problem = outsideRange("static.directionalAtlasSize", s.directionalAtlasSize))
        return problem;
    return outsideRange("static.localAtlasSize", s.localAtlasSize);
}

} // namespace

std::optional<SettingsProblem> findSettingsProblem(const ShadowSettings& s)
{
    const DirectionalShadowSettings& d = s.directional;
    if (auto problem = outsideRange("maxDistance", s.maxDistance))
        return problem;
    if (auto problem = outsideRange("distanceFade", s.distanceFade))
        return problem;
    if (auto problem = outsideRange("directional.atlasSize", d.atlasSize))
        return problem;
    if (static_cast<unsigned>(d.filter) > static_cast<unsigned>(ShadowFilter::PCSS))
        return outOfRange("directional.filter", fmt::format("{}", static_cast<int>(d.filter)));
    if (auto problem = outsideRange("directional.cascadeCount", d.cascadeCount))
        return problem;
    const glm::vec3 r = d.cascadeRatios;
    const SettingRange ratios = shadowSettingsField("directional.cascadeRatios").range;
    if (!withinRange(ratios, r.x) || !withinRange(ratios, r.y) || !withinRange(ratios, r.z) || !(r.x < r.y) ||
        !(r.y < r.z))
        return outOfRange("directional.cascadeRatios", fmt::format("[{}, {}, {}]", r.x, r.y, r.z));
    if (auto problem = outsideRange("directional.cascadeFade", d.cascadeFade))
        return problem;
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
