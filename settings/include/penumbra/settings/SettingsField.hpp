#pragma once

#include "penumbra/settings/SettingRange.hpp"

#include <functional>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace penumbra::settings {

// How a field's value is written in a settings file: a number, a whole number, an array of 3 numbers, one of the
// field's names (an enum), or free text (a file name).
enum class SettingValueKind { Number, Integer, Numbers3, Name, Text };

// One name of a field of names and the enum value it stands for; the table states each name once.
struct SettingName {
    int value;
    std::string_view name;
};
template <typename Enum>
constexpr SettingName nameOf(Enum value, std::string_view name)
{
    return {static_cast<int>(value), name};
}

// A field's value as it moves in and out of a settings struct: its numbers (one; three for Numbers3; the enum's
// value for Name) or its text (Text). An optional field left out (none) has no numbers.
struct SettingValue {
    std::vector<double> numbers;
    std::string text;
};

// One field, declared once: its path in the JSON ("directional.cascadeCount"), its range, the values it allows as
// messages, help and docs state them (written from the range where it is numeric), what it does in a line, the
// command-line option that sets it over a settings file ("--projection"; empty for none), how its value is written,
// the names of a field of names, the numbers of a field of listed numbers (sample counts), and whether it may be left
// out (none).
struct SettingsFieldInfo {
    std::string_view path;
    SettingRange range;
    std::string allowed;
    std::string_view summary;
    std::string_view flag;
    SettingValueKind kind = SettingValueKind::Number;
    std::vector<SettingName> names;
    std::vector<double> listed;
    bool optional = false;
};

// A field of the settings struct `Settings`: its value moves in and out through `get` and `set`; `rule`, where the
// field has one, is what its value must keep beyond its range given the other fields (ratios strictly increasing, a
// largest value at least the smallest): it gives the refused value's text, or nullopt.
template <typename Settings>
struct SettingsField : SettingsFieldInfo {
    std::function<SettingValue(const Settings&)> get;
    std::function<void(Settings&, const SettingValue&)> set;
    std::function<std::optional<std::string>(const Settings&)> rule;
};

namespace detail {

template <typename Value>
SettingValue valueOf(const Value& value)
{
    if constexpr (std::is_same_v<Value, std::string>)
        return {{}, value};
    else if constexpr (std::is_same_v<Value, glm::vec3>)
        return {{value.x, value.y, value.z}, {}};
    else if constexpr (std::is_same_v<Value, std::optional<glm::vec3>>)
        return value ? valueOf(*value) : SettingValue{};
    else if constexpr (std::is_enum_v<Value>)
        return {{static_cast<double>(static_cast<int>(value))}, {}};
    else
        return {{static_cast<double>(value)}, {}};
}

template <typename Value>
void assignValue(Value& value, const SettingValue& from)
{
    if constexpr (std::is_same_v<Value, std::string>)
        value = from.text;
    else if constexpr (std::is_same_v<Value, glm::vec3>)
        value = glm::vec3(static_cast<float>(from.numbers[0]), static_cast<float>(from.numbers[1]),
                          static_cast<float>(from.numbers[2]));
    else if constexpr (std::is_same_v<Value, std::optional<glm::vec3>>)
        value = from.numbers.empty()
                    ? std::nullopt
                    : std::optional(glm::vec3(static_cast<float>(from.numbers[0]), static_cast<float>(from.numbers[1]),
                                              static_cast<float>(from.numbers[2])));
    else if constexpr (std::is_enum_v<Value>)
        value = static_cast<Value>(static_cast<int>(from.numbers[0]));
    else
        value = static_cast<Value>(from.numbers[0]);
}

template <typename Value>
constexpr SettingValueKind kindOf()
{
    if constexpr (std::is_same_v<Value, std::string>)
        return SettingValueKind::Text;
    else if constexpr (std::is_same_v<Value, glm::vec3> || std::is_same_v<Value, std::optional<glm::vec3>>)
        return SettingValueKind::Numbers3;
    else if constexpr (std::is_enum_v<Value>)
        return SettingValueKind::Name;
    else if constexpr (std::is_integral_v<Value>)
        return SettingValueKind::Integer;
    else
        return SettingValueKind::Number;
}

// "a, b, c": the names of a field of names, as `allowed` lists them.
std::string joinedNames(const std::vector<SettingName>& names);
// "16, 32, 64": listed numbers.
std::string joinedNumbers(const std::vector<double>& numbers);

} // namespace detail

// A field reading and writing the member that `member` (a generic lambda returning a reference, for const settings
// and not: [](auto& s) -> auto& { return s.contact.steps; }) picks out; its kind follows the member's type.
template <typename Settings, typename Member>
SettingsField<Settings> field(std::string_view path, SettingRange range, std::string allowed, std::string_view summary,
                              Member member, std::string_view flag = {})
{
    using Value = std::remove_cvref_t<decltype(member(std::declval<Settings&>()))>;
    SettingsField<Settings> result;
    result.path = path;
    result.range = range;
    result.allowed = std::move(allowed);
    result.summary = summary;
    result.flag = flag;
    result.kind = detail::kindOf<Value>();
    result.optional = std::is_same_v<Value, std::optional<glm::vec3>>;
    result.get = [member](const Settings& s) { return detail::valueOf(member(s)); };
    result.set = [member](Settings& s, const SettingValue& value) { detail::assignValue(member(s), value); };
    return result;
}

// A number (or whole number) in `range`, which `allowed` states.
template <typename Settings, typename Member>
SettingsField<Settings> numeric(std::string_view path, SettingRange range, std::string_view summary, Member member,
                                std::string_view flag = {})
{
    return field<Settings>(path, range, rangeText(range), summary, member, flag);
}

// A field of names: an enum's values, each named once here.
template <typename Settings, typename Member>
SettingsField<Settings> named(std::string_view path, std::vector<SettingName> names, std::string_view summary,
                              Member member, std::string_view flag = {})
{
    SettingsField<Settings> result = field<Settings>(path, {}, detail::joinedNames(names), summary, member, flag);
    result.names = std::move(names);
    return result;
}

// A number that is one of `values` (the Poisson sample counts, MSAA's sample counts).
template <typename Settings, typename Member>
SettingsField<Settings> listed(std::string_view path, std::vector<double> values, std::string_view summary,
                               Member member, std::string_view flag = {})
{
    SettingsField<Settings> result = field<Settings>(path, {}, detail::joinedNumbers(values), summary, member, flag);
    result.listed = std::move(values);
    return result;
}

// The field with `rule` (SettingsField::rule).
template <typename Settings, typename Rule>
SettingsField<Settings> withRule(SettingsField<Settings> field, Rule rule)
{
    field.rule = std::move(rule);
    return field;
}

} // namespace penumbra::settings
