#include "penumbra/settings/SettingsTable.hpp"

#include "JsonValue.hpp"
#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

namespace penumbra::settings::detail {
namespace {

// A value as a settings file would hold it; floats at their shortest (0.1, not the double 0.100000001).
std::string settingJsonText(const nlohmann::ordered_json& value)
{
    if (value.is_array()) {
        std::string items;
        for (const nlohmann::ordered_json& item : value)
            items += (items.empty() ? "" : ", ") + settingJsonText(item);
        return "[" + items + "]";
    }
    if (value.is_number_float())
        return fmt::format("{}", value.get<float>());
    if (value.is_string())
        return value.get<std::string>();
    return value.dump();
}

} // namespace

std::string joinedNames(const std::vector<SettingName>& names)
{
    std::string text;
    for (const SettingName& entry : names)
        text += fmt::format("{}{}", text.empty() ? "" : ", ", entry.name);
    return text;
}

std::string joinedNumbers(const std::vector<double>& numbers) { return fmt::format("{}", fmt::join(numbers, ", ")); }

SettingValue parseSettingText(const SettingsFieldInfo& field, std::string_view text, std::string_view source)
{
    nlohmann::json value = std::string(text);
    if (field.optional && text == "none") {
        value = nullptr; // settingValueText's word for an optional field left out
    } else if (field.kind != SettingValueKind::Name && field.kind != SettingValueKind::Text) {
        value = nlohmann::json::parse(text, nullptr, false);
        if (value.is_discarded())
            throw rhi::Error(fmt::format("{}: '{}' is not a value, allowed {}", field.path, text, field.allowed));
    }
    return settingValueFromJson(value, field, source);
}

std::string settingValueText(const SettingsFieldInfo& field, const SettingValue& value)
{
    if (field.optional && value.numbers.empty())
        return "none";
    return settingJsonText(jsonOfSettingValue(field, value));
}

std::optional<std::string> valueOutside(const SettingsFieldInfo& field, const SettingValue& value)
{
    const auto numberText = [&field](double number) {
        return field.kind == SettingValueKind::Number ? fmt::format("{}", static_cast<float>(number))
                                                      : fmt::format("{}", static_cast<std::int64_t>(number));
    };
    switch (field.kind) {
    case SettingValueKind::Text:
        return std::nullopt;
    case SettingValueKind::Name:
        for (const SettingName& entry : field.names)
            if (entry.value == static_cast<int>(value.numbers[0]))
                return std::nullopt;
        return numberText(value.numbers[0]);
    case SettingValueKind::Numbers3:
        for (const double number : value.numbers)
            if (!withinRange(field.range, number))
                return settingValueText(field, value);
        return std::nullopt;
    case SettingValueKind::Number:
    case SettingValueKind::Integer:
        break;
    }
    const double number = value.numbers[0];
    const bool listedOut =
        !field.listed.empty() && std::find(field.listed.begin(), field.listed.end(), number) == field.listed.end();
    if (listedOut || !withinRange(field.range, number))
        return numberText(number);
    return std::nullopt;
}

void throwProblem(std::string_view source, const SettingsProblem& problem)
{
    throw rhi::Error(fmt::format("{}{}{}: {}, allowed {}", source, source.empty() ? "" : ": ", problem.field,
                                 problem.what, problem.allowed));
}

void throwNoSuchField(std::string_view path)
{
    throw rhi::Error(fmt::format("{}: no settings field has this path", path));
}

} // namespace penumbra::settings::detail
