#include "penumbra/shadows/ShadowSettingsJson.hpp"

#include "ShadowSettingsCheck.hpp"
#include "penumbra/rhi/AtomicFile.hpp"
#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

namespace penumbra::shadows {
namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

// Paths a settings file once had, still read as the current ones, but not both at once (spot and point lights were
// once "other" lights).
struct OldPath {
    std::string_view old;
    std::string_view current;
};
constexpr std::array<OldPath, 2> kOldPaths{{{"other", "local"}, {"static.otherAtlasSize", "static.localAtlasSize"}}};

std::string currentPath(std::string path)
{
    for (const OldPath& entry : kOldPaths)
        if (path == entry.old)
            return std::string(entry.current);
    return path;
}

const ShadowSettingsField* fieldAt(std::string_view path)
{
    for (const ShadowSettingsField& field : shadowSettingsFields())
        if (field.path == path)
            return &field;
    return nullptr;
}

// The names that may follow `prefix` ("" or "directional."), in the table's order: "atlasSize, filter, ...".
std::string keysUnder(std::string_view prefix)
{
    std::vector<std::string_view> keys;
    for (const ShadowSettingsField& field : shadowSettingsFields()) {
        if (!field.path.starts_with(prefix))
            continue;
        const std::string_view rest = field.path.substr(prefix.size());
        const std::string_view key = rest.substr(0, rest.find('.'));
        if (std::find(keys.begin(), keys.end(), key) == keys.end())
            keys.push_back(key);
    }
    return fmt::format("{}", fmt::join(keys, ", "));
}

// Reads a settings file's objects into ShadowSettings through the fields' table, naming every problem by its source
// and field path.
class SettingsReader {
public:
    explicit SettingsReader(std::string_view source) : source_(source) {}

    // The object at `prefix` ("" for the top level, "directional." for a group).
    void readObject(const Json& object, const std::string& prefix, ShadowSettings& settings) const
    {
        if (!object.is_object())
            throw rhi::Error(fmt::format("{}: {}: expected an object, got {}", source_,
                                         prefix.empty() ? "(top level)" : prefix.substr(0, prefix.size() - 1),
                                         object.dump()));
        refuseBothPaths(object, prefix);
        for (const auto& [key, value] : object.items()) {
            const std::string path = currentPath(prefix + key);
            if (const ShadowSettingsField* field = fieldAt(path))
                field->set(settings, numbers(value, *field));
            else if (!keysUnder(path + ".").empty())
                readObject(value, path + ".", settings);
            else
                throw rhi::Error(
                    fmt::format("{}: {}{}: unknown field, allowed {}", source_, prefix, key, keysUnder(prefix)));
        }
    }

    // A field's value as ShadowSettingsField::set takes it.
    std::vector<double> numbers(const Json& value, const ShadowSettingsField& field) const
    {
        switch (field.kind) {
        case SettingValueKind::Number:
            return {number(value, field)};
        case SettingValueKind::Integer:
            return {integer(value, field)};
        case SettingValueKind::Numbers3:
            if (!value.is_array() || value.size() != 3)
                fail(field, fmt::format("expected an array of 3 numbers, got {}", value.dump()));
            return {number(value[0], field), number(value[1], field), number(value[2], field)};
        case SettingValueKind::Name:
            if (value.is_string())
                for (const SettingName& entry : field.names)
                    if (entry.name == value.get<std::string>())
                        return {static_cast<double>(entry.value)};
            fail(field, fmt::format("unknown value {}", value.dump()));
        }
        fail(field, "has no kind");
    }

private:
    [[noreturn]] void fail(const ShadowSettingsField& field, std::string_view what) const
    {
        throw rhi::Error(fmt::format("{}: {}: {}, allowed {}", source_, field.path, what, field.allowed));
    }

    double number(const Json& value, const ShadowSettingsField& field) const
    {
        if (!value.is_number())
            fail(field, fmt::format("expected a number, got {}", value.dump()));
        const double d = value.get<double>();
        if (!(std::abs(d) <= std::numeric_limits<float>::max()))
            fail(field, fmt::format("{} is out of range", value.dump()));
        return static_cast<double>(static_cast<float>(d));
    }

    double integer(const Json& value, const ShadowSettingsField& field) const
    {
        if (!value.is_number_integer())
            fail(field, fmt::format("expected an integer, got {}", value.dump()));
        const auto i = value.get<std::int64_t>();
        if (i < 0 || i > std::numeric_limits<std::uint32_t>::max())
            fail(field, fmt::format("{} is out of range", value.dump()));
        return static_cast<double>(i);
    }

    void refuseBothPaths(const Json& object, std::string_view prefix) const
    {
        for (const OldPath& entry : kOldPaths) {
            if (!entry.old.starts_with(prefix) || !entry.current.starts_with(prefix))
                continue;
            const std::string_view old = entry.old.substr(prefix.size());
            const std::string_view current = entry.current.substr(prefix.size());
            if (old.find('.') == std::string_view::npos && object.contains(old) && object.contains(current))
                throw rhi::Error(fmt::format("{}: {} and {} are one field (the old and the current name); give only {}",
                                             source_, entry.old, entry.current, entry.current));
        }
    }

    std::string_view source_;
};

// Throws rhi::Error "<source>: <field>: <what>, allowed <range>" for the first field out of range.
void checkRanges(const ShadowSettings& settings, std::string_view source)
{
    if (const auto problem = detail::findSettingsProblem(settings))
        throw rhi::Error(
            fmt::format("{}: {}: {}, allowed {}", source, problem->field, problem->what, problem->allowed));
}

// A field's value as the settings file holds it.
OrderedJson jsonValue(const ShadowSettingsField& field, const ShadowSettings& settings)
{
    const std::vector<double> numbers = field.get(settings);
    switch (field.kind) {
    case SettingValueKind::Number:
        return static_cast<float>(numbers[0]);
    case SettingValueKind::Integer:
        return static_cast<std::uint32_t>(numbers[0]);
    case SettingValueKind::Numbers3:
        return {static_cast<float>(numbers[0]), static_cast<float>(numbers[1]), static_cast<float>(numbers[2])};
    case SettingValueKind::Name:
        for (const SettingName& entry : field.names)
            if (entry.value == static_cast<int>(numbers[0]))
                return entry.name;
        break;
    }
    return "";
}

std::optional<int> valueOf(std::string_view path, std::string_view name)
{
    for (const SettingName& entry : shadowSettingsField(path).names)
        if (entry.name == name)
            return entry.value;
    return std::nullopt;
}

// "directional.cascadeCount" as the JSON pointer "/directional/cascadeCount".
OrderedJson::json_pointer pointerOf(std::string_view path)
{
    std::string pointer = "/" + std::string(path);
    for (char& c : pointer)
        c = c == '.' ? '/' : c;
    return OrderedJson::json_pointer(pointer);
}

// A value as a settings file would hold it; floats at their shortest (0.1, not toJson's double 0.100000001).
std::string valueText(const OrderedJson& value)
{
    if (value.is_array()) {
        std::string items;
        for (const OrderedJson& item : value)
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
    return valueText(jsonValue(shadowSettingsField(path), settings));
}

void setSettingsField(ShadowSettings& settings, std::string_view path, std::string_view text)
{
    const ShadowSettingsField& field = shadowSettingsField(path);
    Json value = std::string(text);
    if (field.kind != SettingValueKind::Name) {
        value = Json::parse(text, nullptr, false);
        if (value.is_discarded())
            throw rhi::Error(fmt::format("{}: '{}' is not a value, allowed {}", path, text, field.allowed));
    }
    const std::string_view source = "settings";
    ShadowSettings changed = settings;
    field.set(changed, SettingsReader(source).numbers(value, field));
    checkRanges(changed, source);
    settings = changed;
}

std::optional<StaticShadowUpdate> parseStaticShadowUpdate(std::string_view name)
{
    const std::optional<int> value = valueOf("static.update", name);
    return value ? std::optional(static_cast<StaticShadowUpdate>(*value)) : std::nullopt;
}

std::optional<RealtimeCasters> parseRealtimeCasters(std::string_view name)
{
    const std::optional<int> value = valueOf("static.realtimeCasters", name);
    return value ? std::optional(static_cast<RealtimeCasters>(*value)) : std::nullopt;
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
    SettingsReader(sourceName).readObject(root, "", settings);
    checkRanges(settings, sourceName);
    return settings;
}

std::string toJson(const ShadowSettings& settings)
{
    OrderedJson root;
    for (const ShadowSettingsField& field : shadowSettingsFields())
        root[pointerOf(field.path)] = jsonValue(field, settings);
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
