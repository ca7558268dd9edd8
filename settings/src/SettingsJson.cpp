#include "penumbra/settings/SettingsTable.hpp"

#include "JsonValue.hpp"
#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

namespace penumbra::settings::detail {
namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

// Reads a settings file's objects through the fields' table, naming every problem by its source and field path.
class SettingsJsonReader {
public:
    SettingsJsonReader(std::string_view source, const FieldList& fields, std::span<const OldPath> oldPaths,
                       const FieldSetter& set)
        : source_(source), fields_(fields), oldPaths_(oldPaths), set_(set)
    {
    }

    // The object at `prefix` ("" for the top level, "directional." for a group).
    void readObject(const Json& object, const std::string& prefix) const
    {
        if (!object.is_object())
            throw rhi::Error(fmt::format("{}: {}: expected an object, got {}", source_,
                                         prefix.empty() ? "(top level)" : prefix.substr(0, prefix.size() - 1),
                                         object.dump()));
        refuseBothPaths(object, prefix);
        for (const auto& [key, value] : object.items()) {
            const std::string path = currentPath(prefix + key);
            if (const SettingsFieldInfo* field = fieldAt(path))
                set_(*field, settingValueFromJson(value, *field, source_));
            else if (!keysUnder(path + ".").empty())
                readObject(value, path + ".");
            else
                throw rhi::Error(
                    fmt::format("{}: {}{}: unknown field, allowed {}", source_, prefix, key, keysUnder(prefix)));
        }
    }

private:
    std::string currentPath(std::string path) const
    {
        for (const OldPath& entry : oldPaths_)
            if (path == entry.old)
                return std::string(entry.current);
        return path;
    }

    const SettingsFieldInfo* fieldAt(std::string_view path) const
    {
        for (const SettingsFieldInfo* field : fields_)
            if (field->path == path)
                return field;
        return nullptr;
    }

    // The names that may follow `prefix` ("" or "directional."), in the table's order: "atlasSize, filter, ...".
    std::string keysUnder(std::string_view prefix) const
    {
        std::vector<std::string_view> keys;
        for (const SettingsFieldInfo* field : fields_) {
            if (!field->path.starts_with(prefix))
                continue;
            const std::string_view rest = field->path.substr(prefix.size());
            const std::string_view key = rest.substr(0, rest.find('.'));
            if (std::find(keys.begin(), keys.end(), key) == keys.end())
                keys.push_back(key);
        }
        return fmt::format("{}", fmt::join(keys, ", "));
    }

    void refuseBothPaths(const Json& object, std::string_view prefix) const
    {
        for (const OldPath& entry : oldPaths_) {
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
    const FieldList& fields_;
    std::span<const OldPath> oldPaths_;
    const FieldSetter& set_;
};

// "directional.cascadeCount" as the JSON pointer "/directional/cascadeCount".
OrderedJson::json_pointer pointerOf(std::string_view path)
{
    std::string pointer = "/" + std::string(path);
    for (char& c : pointer)
        c = c == '.' ? '/' : c;
    return OrderedJson::json_pointer(pointer);
}

} // namespace

void readSettingsJson(std::string_view json, std::string_view source, const FieldList& fields,
                      std::span<const OldPath> oldPaths, const FieldSetter& set)
{
    Json root;
    try {
        root = Json::parse(json);
    } catch (const Json::exception& e) { // parse_error, and out_of_range for a number beyond double (1e382)
        throw rhi::Error(fmt::format("{}: not valid JSON: {}", source, e.what()));
    }
    SettingsJsonReader(source, fields, oldPaths, set).readObject(root, "");
}

std::string writeSettingsJson(const FieldList& fields, const FieldGetter& get)
{
    OrderedJson root = OrderedJson::object();
    for (const SettingsFieldInfo* field : fields) {
        const SettingValue value = get(*field);
        if (field->optional && value.numbers.empty())
            continue;
        root[pointerOf(field->path)] = jsonOfSettingValue(*field, value);
    }
    return root.dump(2) + "\n";
}

} // namespace penumbra::settings::detail
