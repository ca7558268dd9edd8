#include "penumbra/shadows/ShadowSettingsJson.hpp"

#include "ShadowSettingsCheck.hpp"
#include "penumbra/rhi/AtomicFile.hpp"
#include "penumbra/rhi/Error.hpp"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

namespace penumbra::shadows {
namespace {

using Json = nlohmann::json;

template <typename Enum>
struct EnumName {
    Enum value;
    std::string_view name;
};

std::array<EnumName<ShadowFilter>, kShadowFilterCount> jsonFilterNames()
{
    std::array<EnumName<ShadowFilter>, kShadowFilterCount> names{};
    for (std::size_t i = 0; i < names.size(); ++i)
        names[i] = {shadowFilters()[i].filter, shadowFilters()[i].json};
    return names;
}
const std::array<EnumName<ShadowFilter>, kShadowFilterCount> filterNames = jsonFilterNames();
constexpr std::array<EnumName<CascadeBlend>, 3> blendNames{
    {{CascadeBlend::Hard, "hard"}, {CascadeBlend::Soft, "soft"}, {CascadeBlend::Dither, "dither"}}};
std::array<EnumName<CascadeProjection>, kCascadeProjectionCount> jsonProjectionNames()
{
    std::array<EnumName<CascadeProjection>, kCascadeProjectionCount> names{};
    for (std::size_t i = 0; i < names.size(); ++i)
        names[i] = {cascadeProjectionNames()[i].projection, cascadeProjectionNames()[i].name};
    return names;
}
const std::array<EnumName<CascadeProjection>, kCascadeProjectionCount> projections = jsonProjectionNames();
constexpr std::array<EnumName<rhi::Format>, 3> formatNames{
    {{rhi::Format::D16, "d16"}, {rhi::Format::D24S8, "d24s8"}, {rhi::Format::D32F, "d32f"}}};

constexpr std::array<EnumName<PointShadowMode>, 2> pointModeNames{
    {{PointShadowMode::Atlas, "atlas"}, {PointShadowMode::CubeMap, "cubemap"}}};

constexpr std::array<EnumName<StaticShadowUpdate>, 3> updateNames{{{StaticShadowUpdate::EveryFrame, "everyFrame"},
                                                                   {StaticShadowUpdate::OnChange, "onChange"},
                                                                   {StaticShadowUpdate::OnDemand, "onDemand"}}};
constexpr std::array<EnumName<RealtimeCasters>, 2> realtimeCasterNames{
    {{RealtimeCasters::All, "all"}, {RealtimeCasters::Dynamic, "dynamic"}}};

template <typename Enum, std::size_t N>
std::string_view nameOf(const std::array<EnumName<Enum>, N>& names, Enum value)
{
    for (const auto& n : names)
        if (n.value == value)
            return n.name;
    return "";
}

// Reads one JSON object's fields into a struct, naming every problem by its field path.
class FieldReader {
public:
    FieldReader(std::string_view source, std::string prefix) : source_(source), prefix_(std::move(prefix)) {}

    [[noreturn]] void fail(std::string_view key, std::string_view what) const
    {
        const std::string field = prefix_ + std::string(key);
        throw rhi::Error(fmt::format("{}: {}: {}, allowed {}", source_, field, what, detail::allowedValues(field)));
    }

    float number(const Json& value, std::string_view key) const
    {
        if (!value.is_number())
            fail(key, fmt::format("expected a number, got {}", value.dump()));
        const double d = value.get<double>();
        if (!(std::abs(d) <= std::numeric_limits<float>::max()))
            fail(key, fmt::format("{} is out of range", value.dump()));
        return static_cast<float>(d);
    }

    std::uint32_t integer(const Json& value, std::string_view key) const
    {
        if (!value.is_number_integer())
            fail(key, fmt::format("expected an integer, got {}", value.dump()));
        const auto i = value.get<std::int64_t>();
        if (i < 0 || i > std::numeric_limits<std::uint32_t>::max())
            fail(key, fmt::format("{} is out of range", value.dump()));
        return static_cast<std::uint32_t>(i);
    }

    template <typename Enum, std::size_t N>
    Enum enumeration(const Json& value, std::string_view key, const std::array<EnumName<Enum>, N>& names) const
    {
        if (value.is_string())
            if (const std::optional<Enum> known = valueOf(names, value.get<std::string>()))
                return *known;
        fail(key, fmt::format("unknown value {}", value.dump()));
    }

    glm::vec3 vec3(const Json& value, std::string_view key) const
    {
        if (!value.is_array() || value.size() != 3)
            fail(key, fmt::format("expected an array of 3 numbers, got {}", value.dump()));
        return {number(value[0], key), number(value[1], key), number(value[2], key)};
    }

    void requireObject(const Json& value, std::string_view what) const
    {
        if (!value.is_object())
            throw rhi::Error(fmt::format("{}: {}: expected an object, got {}", source_, what, value.dump()));
    }

    // Spot and point lights were once "other" lights: `oldName` is still read as `name`, but not both at once.
    void refuseBothNames(const Json& object, std::string_view name, std::string_view oldName) const
    {
        if (object.contains(name) && object.contains(oldName))
            throw rhi::Error(
                fmt::format("{}: {}{} and {}{} are one field (the old and the current name); give only {}{}", source_,
                            prefix_, oldName, prefix_, name, prefix_, name));
    }

    [[noreturn]] void unknown(const std::string& key, std::string_view known) const
    {
        throw rhi::Error(fmt::format("{}: {}{}: unknown field, allowed {}", source_, prefix_, key, known));
    }

private:
    std::string_view source_;
    std::string prefix_;
};

void readDirectional(const Json& object, std::string_view source, DirectionalShadowSettings& d)
{
    const FieldReader r(source, "directional.");
    r.requireObject(object, "directional");
    for (const auto& [key, value] : object.items()) {
        if (key == "atlasSize")
            d.atlasSize = r.integer(value, key);
        else if (key == "filter")
            d.filter = r.enumeration(value, key, filterNames);
        else if (key == "cascadeCount")
            d.cascadeCount = r.integer(value, key);
        else if (key == "cascadeRatios")
            d.cascadeRatios = r.vec3(value, key);
        else if (key == "cascadeFade")
            d.cascadeFade = r.number(value, key);
        else if (key == "cascadeBlend")
            d.cascadeBlend = r.enumeration(value, key, blendNames);
        else if (key == "projection")
            d.projection = r.enumeration(value, key, projections);
        else if (key == "atlasFormat")
            d.atlasFormat = r.enumeration(value, key, formatNames);
        else
            r.unknown(key, "atlasSize, filter, cascadeCount, cascadeRatios, cascadeFade, cascadeBlend, projection, "
                           "atlasFormat");
    }
}

void readLocal(const Json& object, std::string_view source, LocalShadowSettings& o)
{
    const FieldReader r(source, "local.");
    r.requireObject(object, "local");
    for (const auto& [key, value] : object.items()) {
        if (key == "atlasSize")
            o.atlasSize = r.integer(value, key);
        else if (key == "filter")
            o.filter = r.enumeration(value, key, filterNames);
        else if (key == "atlasFormat")
            o.atlasFormat = r.enumeration(value, key, formatNames);
        else if (key == "pointMode")
            o.pointMode = r.enumeration(value, key, pointModeNames);
        else if (key == "cubeMapSize")
            o.cubeMapSize = r.integer(value, key);
        else if (key == "nearPlane")
            o.nearPlane = r.number(value, key);
        else
            r.unknown(key, "atlasSize, filter, atlasFormat, pointMode, cubeMapSize, nearPlane");
    }
}

void readSoft(const Json& object, std::string_view source, SoftShadowSettings& s)
{
    const FieldReader r(source, "soft.");
    r.requireObject(object, "soft");
    for (const auto& [key, value] : object.items()) {
        if (key == "blockerSearchScale")
            s.blockerSearchScale = r.number(value, key);
        else if (key == "penumbraScale")
            s.penumbraScale = r.number(value, key);
        else if (key == "blockerSamples")
            s.blockerSamples = r.integer(value, key);
        else if (key == "filterSamples")
            s.filterSamples = r.integer(value, key);
        else if (key == "minPenumbraTexels")
            s.minPenumbraTexels = r.number(value, key);
        else if (key == "maxPenumbraTexels")
            s.maxPenumbraTexels = r.number(value, key);
        else if (key == "poissonRadiusTexels")
            s.poissonRadiusTexels = r.number(value, key);
        else
            r.unknown(key, "blockerSearchScale, penumbraScale, blockerSamples, filterSamples, minPenumbraTexels, "
                           "maxPenumbraTexels, poissonRadiusTexels");
    }
}

void readStatic(const Json& object, std::string_view source, StaticShadowSettings& s)
{
    const FieldReader r(source, "static.");
    r.requireObject(object, "static");
    r.refuseBothNames(object, "localAtlasSize", "otherAtlasSize");
    for (const auto& [key, value] : object.items()) {
        if (key == "update")
            s.update = r.enumeration(value, key, updateNames);
        else if (key == "realtimeCasters")
            s.realtimeCasters = r.enumeration(value, key, realtimeCasterNames);
        else if (key == "directionalAtlasSize")
            s.directionalAtlasSize = r.integer(value, key);
        else if (key == "localAtlasSize" || key == "otherAtlasSize")
            s.localAtlasSize = r.integer(value, "localAtlasSize");
        else
            r.unknown(key, "update, realtimeCasters, directionalAtlasSize, localAtlasSize");
    }
}

template <typename Enum, std::size_t N>
std::optional<Enum> valueOf(const std::array<EnumName<Enum>, N>& names, std::string_view name)
{
    for (const auto& n : names)
        if (n.name == name)
            return n.value;
    return std::nullopt;
}

// "directional.cascadeCount" as the JSON pointer "/directional/cascadeCount".
Json::json_pointer pointerOf(std::string_view path)
{
    std::string pointer = "/" + std::string(path);
    for (char& c : pointer)
        c = c == '.' ? '/' : c;
    return Json::json_pointer(pointer);
}

// A value as a settings file would hold it; floats at their shortest (0.1, not toJson's double 0.100000001).
std::string valueText(const Json& value)
{
    if (value.is_array()) {
        std::string items;
        for (const Json& item : value)
            items += (items.empty() ? "" : ", ") + valueText(item);
        return "[" + items + "]";
    }
    if (value.is_number_float())
        return fmt::format("{}", value.get<float>());
    if (value.is_string())
        return value.get<std::string>();
    return value.dump();
}

} // namespace

std::string settingsFieldText(const ShadowSettings& settings, std::string_view path)
{
    return valueText(Json::parse(toJson(settings)).at(pointerOf(shadowSettingsField(path).path)));
}

void setSettingsField(ShadowSettings& settings, std::string_view path, std::string_view text)
{
    const ShadowSettingsField& field = shadowSettingsField(path);
    Json root = Json::parse(toJson(settings));
    Json& value = root.at(pointerOf(field.path));
    if (value.is_string()) {
        value = std::string(text);
    } else {
        value = Json::parse(text, nullptr, false);
        if (value.is_discarded())
            throw rhi::Error(fmt::format("{}: '{}' is not a value, allowed {}", path, text, field.allowed));
    }
    settings = parseShadowSettings(root.dump(), "settings");
}

std::optional<StaticShadowUpdate> parseStaticShadowUpdate(std::string_view name) { return valueOf(updateNames, name); }

std::optional<RealtimeCasters> parseRealtimeCasters(std::string_view name)
{
    return valueOf(realtimeCasterNames, name);
}

ShadowSettings parseShadowSettings(std::string_view json, std::string_view sourceName)
{
    Json root;
    try {
        root = Json::parse(json);
    } catch (const Json::exception& e) { // parse_error, and out_of_range for a number beyond double (1e382)
        throw rhi::Error(fmt::format("{}: not valid JSON: {}", sourceName, e.what()));
    }
    ShadowSettings settings;
    const FieldReader r(sourceName, "");
    r.requireObject(root, "(top level)");
    r.refuseBothNames(root, "local", "other");
    for (const auto& [key, value] : root.items()) {
        if (key == "maxDistance")
            settings.maxDistance = r.number(value, key);
        else if (key == "distanceFade")
            settings.distanceFade = r.number(value, key);
        else if (key == "directional")
            readDirectional(value, sourceName, settings.directional);
        else if (key == "local" || key == "other")
            readLocal(value, sourceName, settings.local);
        else if (key == "soft")
            readSoft(value, sourceName, settings.soft);
        else if (key == "static")
            readStatic(value, sourceName, settings.staticMaps);
        else
            r.unknown(key, "maxDistance, distanceFade, directional, local, soft, static");
    }
    if (const auto problem = detail::findSettingsProblem(settings))
        throw rhi::Error(
            fmt::format("{}: {}: {}, allowed {}", sourceName, problem->field, problem->what, problem->allowed));
    return settings;
}

std::string toJson(const ShadowSettings& s)
{
    const DirectionalShadowSettings& d = s.directional;
    nlohmann::ordered_json directional;
    directional["atlasSize"] = d.atlasSize;
    directional["filter"] = nameOf(filterNames, d.filter);
    directional["cascadeCount"] = d.cascadeCount;
    directional["cascadeRatios"] = {d.cascadeRatios.x, d.cascadeRatios.y, d.cascadeRatios.z};
    directional["cascadeFade"] = d.cascadeFade;
    directional["cascadeBlend"] = nameOf(blendNames, d.cascadeBlend);
    directional["projection"] = nameOf(projections, d.projection);
    directional["atlasFormat"] = nameOf(formatNames, d.atlasFormat);
    const LocalShadowSettings& o = s.local;
    nlohmann::ordered_json local;
    local["atlasSize"] = o.atlasSize;
    local["filter"] = nameOf(filterNames, o.filter);
    local["atlasFormat"] = nameOf(formatNames, o.atlasFormat);
    local["pointMode"] = nameOf(pointModeNames, o.pointMode);
    local["cubeMapSize"] = o.cubeMapSize;
    local["nearPlane"] = o.nearPlane;
    const SoftShadowSettings& f = s.soft;
    nlohmann::ordered_json soft;
    soft["blockerSearchScale"] = f.blockerSearchScale;
    soft["penumbraScale"] = f.penumbraScale;
    soft["blockerSamples"] = f.blockerSamples;
    soft["filterSamples"] = f.filterSamples;
    soft["minPenumbraTexels"] = f.minPenumbraTexels;
    soft["maxPenumbraTexels"] = f.maxPenumbraTexels;
    soft["poissonRadiusTexels"] = f.poissonRadiusTexels;
    nlohmann::ordered_json staticMaps;
    staticMaps["update"] = nameOf(updateNames, s.staticMaps.update);
    staticMaps["realtimeCasters"] = nameOf(realtimeCasterNames, s.staticMaps.realtimeCasters);
    staticMaps["directionalAtlasSize"] = s.staticMaps.directionalAtlasSize;
    staticMaps["localAtlasSize"] = s.staticMaps.localAtlasSize;
    nlohmann::ordered_json root;
    root["maxDistance"] = s.maxDistance;
    root["distanceFade"] = s.distanceFade;
    root["directional"] = std::move(directional);
    root["local"] = std::move(local);
    root["soft"] = std::move(soft);
    root["static"] = std::move(staticMaps);
    return root.dump(2) + "\n";
}

ShadowSettings loadShadowSettings(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw rhi::Error(fmt::format("{}: cannot open: {}", path.string(), std::strerror(errno)));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad())
        throw rhi::Error(fmt::format("{}: cannot read: {}", path.string(), std::strerror(errno)));
    return parseShadowSettings(text.str(), path.string());
}

void saveShadowSettings(const std::filesystem::path& path, const ShadowSettings& settings)
{
    validate(settings);
    rhi::writeFileAtomically(path, toJson(settings));
}

} // namespace penumbra::shadows
