#include "JsonValue.hpp"

#include "penumbra/rhi/Error.hpp"

#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <fmt/format.h>
#include <limits>
#include <string>

namespace penumbra::settings::detail {
namespace {

[[noreturn]] void refuseJsonValue(const SettingsFieldInfo& field, std::string_view source, std::string_view what)
{
    throw rhi::Error(fmt::format("{}: {}: {}, allowed {}", source, field.path, what, field.allowed));
}

double jsonNumber(const nlohmann::json& value, const SettingsFieldInfo& field, std::string_view source)
{
    if (!value.is_number())
        refuseJsonValue(field, source, fmt::format("expected a number, got {}", value.dump()));
    const double d = value.get<double>();
    if (!(std::abs(d) <= std::numeric_limits<float>::max()))
        refuseJsonValue(field, source, fmt::format("{} is out of range", value.dump()));
    return static_cast<double>(static_cast<float>(d));
}

double jsonInteger(const nlohmann::json& value, const SettingsFieldInfo& field, std::string_view source)
{
    if (!value.is_number_integer())
        refuseJsonValue(field, source, fmt::format("expected an integer, got {}", value.dump()));
    const auto i = value.get<std::int64_t>();
    if (i < 0 || i > std::numeric_limits<std::uint32_t>::max())
        refuseJsonValue(field, source, fmt::format("{} is out of range", value.dump()));
    return static_cast<double>(i);
}

// The float a field holds, as the double nearest its shortest decimal text: a file says 0.3, not the float's exact
// 0.30000001192092896, and reads back to the same float.
double shortestFloat(double number)
{
    return std::strtod(fmt::format("{}", static_cast<float>(number)).c_str(), nullptr);
}

} // namespace

SettingValue settingValueFromJson(const nlohmann::json& value, const SettingsFieldInfo& field, std::string_view source)
{
    switch (field.kind) {
    case SettingValueKind::Number:
        return {{jsonNumber(value, field, source)}, {}};
    case SettingValueKind::Integer:
        return {{jsonInteger(value, field, source)}, {}};
    case SettingValueKind::Numbers3:
        if (field.optional && value.is_null())
            return {};
        if (!value.is_array() || value.size() != 3)
            refuseJsonValue(field, source, fmt::format("expected an array of 3 numbers, got {}", value.dump()));
        return {{jsonNumber(value[0], field, source), jsonNumber(value[1], field, source),
                 jsonNumber(value[2], field, source)},
                {}};
    case SettingValueKind::Name:
        if (value.is_string())
            for (const SettingName& entry : field.names)
                if (entry.name == value.get<std::string>())
                    return {{static_cast<double>(entry.value)}, {}};
        refuseJsonValue(field, source, fmt::format("unknown value {}", value.dump()));
    case SettingValueKind::Text:
        if (!value.is_string())
            refuseJsonValue(field, source, fmt::format("expected a string, got {}", value.dump()));
        return {{}, value.get<std::string>()};
    }
    refuseJsonValue(field, source, "has no kind");
}

nlohmann::ordered_json jsonOfSettingValue(const SettingsFieldInfo& field, const SettingValue& value)
{
    switch (field.kind) {
    case SettingValueKind::Number:
        return shortestFloat(value.numbers[0]);
    case SettingValueKind::Integer:
        return static_cast<std::uint32_t>(value.numbers[0]);
    case SettingValueKind::Numbers3:
        if (value.numbers.empty())
            return nullptr;
        return {shortestFloat(value.numbers[0]), shortestFloat(value.numbers[1]), shortestFloat(value.numbers[2])};
    case SettingValueKind::Name:
        for (const SettingName& entry : field.names)
            if (entry.value == static_cast<int>(value.numbers[0]))
                return entry.name;
        break;
    case SettingValueKind::Text:
        return value.text;
    }
    return "";
}

} // namespace penumbra::settings::detail
