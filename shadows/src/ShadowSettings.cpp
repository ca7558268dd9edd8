#include "penumbra/shadows/ShadowSettings.hpp"

#include "ShadowSettingsCheck.hpp"
#include "penumbra/rhi/Error.hpp"

#include <array>
#include <type_traits>
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
// Depth steps of a constant depth bias: up to the 500 000 of Catlike Coding's "Directional Shadows" (section 4.1).
constexpr SettingRange kDepthBias{SettingRangeKind::Closed, 0, 1000000};

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

// A field's value as the numbers ShadowSettingsField::get gives, and back.
template <typename Value>
std::vector<double> numbersOf(const Value& value)
{
    if constexpr (std::is_enum_v<Value>)
        return {static_cast<double>(static_cast<int>(value))};
    else
        return {static_cast<double>(value)};
}
std::vector<double> numbersOf(const glm::vec3& value) { return {value.x, value.y, value.z}; }

template <typename Value>
void assign(Value& value, std::span<const double> numbers)
{
    if constexpr (std::is_enum_v<Value>)
        value = static_cast<Value>(static_cast<int>(numbers[0]));
    else
        value = static_cast<Value>(numbers[0]);
}
void assign(glm::vec3& value, std::span<const double> numbers)
{
    value = glm::vec3(static_cast<float>(numbers[0]), static_cast<float>(numbers[1]), static_cast<float>(numbers[2]));
}

// A field reading and writing the member that `member` (a generic lambda, for const settings and not) picks out;
// its kind follows the member's type.
template <typename Member>
ShadowSettingsField field(std::string_view path, SettingRange range, std::string allowed, std::string_view summary,
                          Member member, std::vector<SettingName> names = {}, std::string_view flag = {})
{
    using Value = std::remove_cvref_t<decltype(member(std::declval<ShadowSettings&>()))>;
    SettingValueKind kind = SettingValueKind::Number;
    if constexpr (std::is_enum_v<Value>)
        kind = SettingValueKind::Name;
    else if constexpr (std::is_same_v<Value, glm::vec3>)
        kind = SettingValueKind::Numbers3;
    else if constexpr (std::is_integral_v<Value>)
        kind = SettingValueKind::Integer;
    return {path,
            range,
            std::move(allowed),
            summary,
            flag,
            kind,
            std::move(names),
            [member](const ShadowSettings& s) { return numbersOf(member(s)); },
            [member](ShadowSettings& s, std::span<const double> numbers) { assign(member(s), numbers); }};
}

template <typename Member>
ShadowSettingsField numeric(std::string_view path, SettingRange range, std::string_view summary, Member member,
                            std::string_view flag = {})
{
    return field(path, range, rangeText(range), summary, member, {}, flag);
}

// A field of names: an enum's values, each named once here.
template <typename Member>
ShadowSettingsField named(std::string_view path, std::vector<SettingName> names, std::string_view summary,
                          Member member, std::string_view flag = {})
{
    std::string allowed;
    for (const SettingName& entry : names)
        allowed += fmt::format("{}{}", allowed.empty() ? "" : ", ", entry.name);
    return field(path, {}, std::move(allowed), summary, member, std::move(names), flag);
}

template <typename Enum>
constexpr SettingName nameOf(Enum value, std::string_view name)
{
    return {static_cast<int>(value), name};
}

std::vector<SettingName> filterNames()
{
    std::vector<SettingName> names;
    for (const ShadowFilterInfo& entry : kFilters)
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

std::vector<ShadowSettingsField> makeFields()
{
    const std::string sampleCounts = fmt::format("{}", fmt::join(kPoissonSampleCounts, ", "));
    const SettingRange poissonRadius{SettingRangeKind::Closed, 0.5, kPenumbraTexels.high};
    const SettingRange unit{SettingRangeKind::Closed, 0, 1};
    return {{
        numeric(
            "maxDistance", {SettingRangeKind::Above, 0.001},
            "view depth beyond which nothing is shadowed, for every light",
            [](auto& s) -> auto& { return s.maxDistance; }),
        numeric(
            "distanceFade", kFraction, "fraction of maxDistance over which shadows fade out",
            [](auto& s) -> auto& { return s.distanceFade; }),
        named(
            "culling", {nameOf(CasterCullingMode::Cpu, "cpu"), nameOf(CasterCullingMode::Gpu, "gpu")},
            "where the realtime atlases' casters are culled per tile: cpu (the planner) or gpu (a compute pass, "
            "indirect draws)",
            [](auto& s) -> auto& { return s.culling; }, "--culling"),
        numeric(
            "directional.atlasSize", kAtlasSizes, "texels per side of the directional atlas",
            [](auto& s) -> auto& { return s.directional.atlasSize; }),
        named(
            "directional.filter", filterNames(), "the directional lights' filter, unless a light sets its own",
            [](auto& s) -> auto& { return s.directional.filter; }),
        numeric(
            "directional.cascadeCount", {SettingRangeKind::Closed, 1, 4}, "cascades per directional light",
            [](auto& s) -> auto& { return s.directional.cascadeCount; }),
        field(
            "directional.cascadeRatios", unit, fmt::format("3 numbers in {}, strictly increasing", rangeText(unit)),
            "ends of cascades 1..3 as fractions of maxDistance",
            [](auto& s) -> auto& { return s.directional.cascadeRatios; }),
        numeric(
            "directional.cascadeFade", kFraction, "fraction of the last cascade over which it fades",
            [](auto& s) -> auto& { return s.directional.cascadeFade; }),
        named(
            "directional.cascadeBlend",
            {nameOf(CascadeBlend::Hard, "hard"), nameOf(CascadeBlend::Soft, "soft"),
             nameOf(CascadeBlend::Dither, "dither")},
            "how the lit pass moves from one cascade to the next",
            [](auto& s) -> auto& { return s.directional.cascadeBlend; }),
        named(
            "directional.projection", projectionSettingNames(),
            "stable: texel-snapped spheres that hold still; close: tiles fitted to the view's slices; depthFit: "
            "tiles fitted to the visible surfaces, split by their depths",
            [](auto& s) -> auto& { return s.directional.projection; }, "--projection"),
        numeric(
            "directional.depthFitSteps", {SettingRangeKind::Closed, 0, 64},
            "depthFit's grid steps per power of two of its tiles' size (0: unquantized)",
            [](auto& s) -> auto& { return s.directional.depthFitSteps; }),
        numeric(
            "directional.depthFitHysteresis", {SettingRangeKind::Closed, 0, 8},
            "grid steps a depthFit tile's fit must shrink inside its size before the tile does",
            [](auto& s) -> auto& { return s.directional.depthFitHysteresis; }),
        named(
            "directional.atlasFormat", depthFormats(), "depth format of the directional atlas",
            [](auto& s) -> auto& { return s.directional.atlasFormat; }),
        numeric(
            "directional.depthBias", kDepthBias,
            "constant depth bias of the directional casters, in depth steps, beside each light's slope-scaled one",
            [](auto& s) -> auto& { return s.directional.depthBias; }, "--directional-depth-bias"),
        numeric(
            "local.atlasSize", kAtlasSizes, "texels per side of the spot and point lights' atlas",
            [](auto& s) -> auto& { return s.local.atlasSize; }, "--local-atlas-size"),
        named(
            "local.filter", filterNames(), "the spot and point lights' filter, unless a light sets its own",
            [](auto& s) -> auto& { return s.local.filter; }),
        named(
            "local.atlasFormat", depthFormats(), "depth format of the local atlas",
            [](auto& s) -> auto& { return s.local.atlasFormat; }),
        named(
            "local.pointMode", {nameOf(PointShadowMode::Atlas, "atlas"), nameOf(PointShadowMode::CubeMap, "cubemap")},
            "point lights in six atlas tiles or in a depth cube map each",
            [](auto& s) -> auto& { return s.local.pointMode; }),
        numeric(
            "local.cubeMapSize", {SettingRangeKind::PowersOfTwo, 64, 4096}, "texels per face side in cubemap mode",
            [](auto& s) -> auto& { return s.local.cubeMapSize; }),
        numeric(
            "local.nearPlane", {SettingRangeKind::Closed, 0.0001, 0.5},
            "shadow near plane as a fraction of the light's range, for lights without one",
            [](auto& s) -> auto& { return s.local.nearPlane; }),
        numeric(
            "local.tileResolution", {SettingRangeKind::PowersOfTwo, 16, 8192},
            "texels per side a spot or point light without its own shadowResolution asks for when its reach fills "
            "the screen",
            [](auto& s) -> auto& { return s.local.tileResolution; }),
        numeric(
            "local.minTileResolution", {SettingRangeKind::PowersOfTwo, 16, 1024},
            "texels per side a light's tile is lowered to, at most, before the light loses its shadow",
            [](auto& s) -> auto& { return s.local.minTileResolution; }),
        numeric(
            "local.depthBias", kDepthBias,
            "constant depth bias of the spot and point casters, in depth steps, beside each light's slope-scaled one",
            [](auto& s) -> auto& { return s.local.depthBias; }, "--local-depth-bias"),
        named(
            "local.spotFovBias", toggleNames(),
            "widens spot shadow frustums as point faces are, so bias and filter taps at the cone's edge stay in the "
            "tile",
            [](auto& s) -> auto& { return s.local.spotFovBias; }, "--spot-fov-bias"),
        named(
            "local.clusterBuild", {nameOf(LightClusterBuild::Cpu, "cpu"), nameOf(LightClusterBuild::Gpu, "gpu")},
            "where the lit pass's clustered light lists are built: cpu, or gpu (a compute pass; the same lists)",
            [](auto& s) -> auto& { return s.local.clusterBuild; }, "--cluster-build"),
        numeric(
            "soft.blockerSearchScale", kScale, "scales PCSS's blocker search region (NVIDIA's w_search)",
            [](auto& s) -> auto& { return s.soft.blockerSearchScale; }),
        numeric(
            "soft.penumbraScale", kScale, "scales PCSS's penumbra estimate (NVIDIA's w_penumbra)",
            [](auto& s) -> auto& { return s.soft.penumbraScale; }),
        field(
            "soft.blockerSamples", {}, sampleCounts, "Poisson disk taps of each blocker search",
            [](auto& s) -> auto& { return s.soft.blockerSamples; }),
        field(
            "soft.filterSamples", {}, sampleCounts, "Poisson disk taps of the soft filters",
            [](auto& s) -> auto& { return s.soft.filterSamples; }),
        numeric(
            "soft.minPenumbraTexels", kPenumbraTexels, "smallest filter radius of PCSS, in texels",
            [](auto& s) -> auto& { return s.soft.minPenumbraTexels; }),
        field(
            "soft.maxPenumbraTexels", kPenumbraTexels, fmt::format("minPenumbraTexels..{}", kPenumbraTexels.high),
            "largest filter radius and blocker search of PCSS, in texels",
            [](auto& s) -> auto& { return s.soft.maxPenumbraTexels; }),
        numeric(
            "soft.poissonRadiusTexels", poissonRadius, "the fixed poisson filter's radius, in texels",
            [](auto& s) -> auto& { return s.soft.poissonRadiusTexels; }),
        named(
            "soft.diskRotation", toggleNames(),
            "turns the poisson and pcss disks per receiver texel (noise instead of the disk's fixed pattern)",
            [](auto& s) -> auto& { return s.soft.diskRotation; }, "--disk-rotation"),
        named(
            "static.update",
            {nameOf(StaticShadowUpdate::EveryFrame, "everyFrame"), nameOf(StaticShadowUpdate::OnChange, "onChange"),
             nameOf(StaticShadowUpdate::OnDemand, "onDemand")},
            "when static shadow maps are drawn; everyFrame keeps none",
            [](auto& s) -> auto& { return s.staticMaps.update; }, "--static-maps"),
        named(
            "static.realtimeCasters",
            {nameOf(RealtimeCasters::All, "all"), nameOf(RealtimeCasters::Dynamic, "dynamic")},
            "which casters the realtime atlases draw while static maps exist",
            [](auto& s) -> auto& { return s.staticMaps.realtimeCasters; }, "--realtime-casters"),
        numeric(
            "static.directionalAtlasSize", kAtlasSizes, "texels per side of the directional lights' static atlas",
            [](auto& s) -> auto& { return s.staticMaps.directionalAtlasSize; }),
        numeric(
            "static.localAtlasSize", kAtlasSizes, "texels per side of the spot and point lights' static atlas",
            [](auto& s) -> auto& { return s.staticMaps.localAtlasSize; }),
        named(
            "contact.shadows", toggleNames(),
            "a short march through the depth buffer towards each directional light, added to its shadow map",
            [](auto& s) -> auto& { return s.contact.shadows; }, "--contact-shadows"),
        numeric(
            "contact.length", {SettingRangeKind::Closed, 0.01, 10}, "metres the contact march goes towards the light",
            [](auto& s) -> auto& { return s.contact.length; }),
        numeric(
            "contact.steps", {SettingRangeKind::Closed, 1, 64}, "depth samples along the contact march",
            [](auto& s) -> auto& { return s.contact.steps; }),
        numeric(
            "contact.thickness", {SettingRangeKind::Closed, 0.001, 10},
            "metres behind a depth sample that the contact march counts as inside its surface",
            [](auto& s) -> auto& { return s.contact.thickness; }),
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
    static const std::vector<ShadowSettingsField> fields = makeFields();
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
        {CascadeProjection::DepthFit, "depthFit"},
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

std::string_view projectionNames() { return shadowSettingsField("directional.projection").allowed; }

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
    if (auto problem = outsideRange("local.tileResolution", o.tileResolution))
        return problem;
    if (auto problem = outsideRange("local.minTileResolution", o.minTileResolution))
        return problem;
    if (o.minTileResolution > o.atlasSize)
        return outOfRange("local.minTileResolution",
                          fmt::format("{} (above local.atlasSize {})", o.minTileResolution, o.atlasSize));
    if (auto problem = outsideRange("local.depthBias", o.depthBias))
        return problem;
    if (static_cast<unsigned>(o.spotFovBias) > static_cast<unsigned>(Toggle::On))
        return outOfRange("local.spotFovBias", fmt::format("{}", static_cast<int>(o.spotFovBias)));
    if (static_cast<unsigned>(o.clusterBuild) > static_cast<unsigned>(LightClusterBuild::Gpu))
        return outOfRange("local.clusterBuild", fmt::format("{}", static_cast<int>(o.clusterBuild)));
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
    if (static_cast<unsigned>(s.diskRotation) > static_cast<unsigned>(Toggle::On))
        return outOfRange("soft.diskRotation", fmt::format("{}", static_cast<int>(s.diskRotation)));
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

std::optional<SettingsProblem> findContactSettingsProblem(const ContactShadowSettings& c)
{
    if (static_cast<unsigned>(c.shadows) > static_cast<unsigned>(Toggle::On))
        return outOfRange("contact.shadows", fmt::format("{}", static_cast<int>(c.shadows)));
    if (auto problem = outsideRange("contact.length", c.length))
        return problem;
    if (auto problem = outsideRange("contact.steps", c.steps))
        return problem;
    return outsideRange("contact.thickness", c.thickness);
}

} // namespace

std::optional<SettingsProblem> findSettingsProblem(const ShadowSettings& s)
{
    const DirectionalShadowSettings& d = s.directional;
    if (auto problem = outsideRange("maxDistance", s.maxDistance))
        return problem;
    if (auto problem = outsideRange("distanceFade", s.distanceFade))
        return problem;
    if (static_cast<unsigned>(s.culling) > static_cast<unsigned>(CasterCullingMode::Gpu))
        return outOfRange("culling", fmt::format("{}", static_cast<int>(s.culling)));
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
    if (auto problem = outsideRange("directional.depthFitSteps", d.depthFitSteps))
        return problem;
    if (auto problem = outsideRange("directional.depthFitHysteresis", d.depthFitHysteresis))
        return problem;
    if (!rhi::isDepthFormat(d.atlasFormat))
        return outOfRange("directional.atlasFormat", std::string(rhi::formatName(d.atlasFormat)));
    if (auto problem = outsideRange("directional.depthBias", d.depthBias))
        return problem;
    if (auto problem = findLocalSettingsProblem(s.local))
        return problem;
    if (auto problem = findSoftSettingsProblem(s.soft))
        return problem;
    if (auto problem = findStaticSettingsProblem(s.staticMaps))
        return problem;
    return findContactSettingsProblem(s.contact);
}

} // namespace detail
} // namespace penumbra::shadows
