#pragma once

#include "penumbra/settings/SettingsField.hpp"

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::settings {

// A path a settings file once had, still read as the current one, but not both at once.
struct OldPath {
    std::string_view old;
    std::string_view current;
};

// One field refused: "<field>: <what>, allowed <allowed>".
struct SettingsProblem {
    std::string field;
    std::string what;
    std::string allowed;
};

namespace detail {

using FieldList = std::vector<const SettingsFieldInfo*>;
using FieldSetter = std::function<void(const SettingsFieldInfo&, const SettingValue&)>;
using FieldGetter = std::function<SettingValue(const SettingsFieldInfo&)>;

// Reads a settings file's JSON, calling `set` for each field it gives. Throws rhi::Error "<source>: <path>: <what>,
// allowed <allowed>" for bad JSON, an unknown field (allowed: the names at its place), a value of the wrong kind or
// an unknown name.
void readSettingsJson(std::string_view json, std::string_view source, const FieldList& fields,
                      std::span<const OldPath> oldPaths, const FieldSetter& set);
// Every field, two-space indented, objects nested by the paths' dots; a field left out (none) is not written.
std::string writeSettingsJson(const FieldList& fields, const FieldGetter& get);
// A value from its text as the command line gives it ("close", "2048", "[1, 2, 3]"); throws rhi::Error naming the
// field (and `source` for a value of the wrong kind).
SettingValue parseSettingText(const SettingsFieldInfo& field, std::string_view text, std::string_view source);
// The value as a settings file holds it, floats at their shortest and names unquoted: "0.1", "[0.1, 0.25, 0.5]",
// "stable"; "none" for a field left out.
std::string settingValueText(const SettingsFieldInfo& field, const SettingValue& value);
// The value's text where it is outside the field's range, names or list; nullopt where it is allowed.
std::optional<std::string> valueOutside(const SettingsFieldInfo& field, const SettingValue& value);
// Throws rhi::Error "<source>: <field>: <what>, allowed <allowed>" (without "<source>: " for an empty source).
[[noreturn]] void throwProblem(std::string_view source, const SettingsProblem& problem);
[[noreturn]] void throwNoSuchField(std::string_view path);

} // namespace detail

// The fields of one settings struct, and everything derived from them: validation with messages that name the
// field and its allowed values, JSON reading and writing, a field's value as text and from text (the command line).
template <typename Settings>
class SettingsTable {
public:
    explicit SettingsTable(std::vector<SettingsField<Settings>> fields, std::vector<OldPath> oldPaths = {})
        : fields_(std::move(fields)), oldPaths_(std::move(oldPaths))
    {
        for (const SettingsField<Settings>& entry : fields_)
            list_.push_back(&entry);
    }
    // list_ points into fields_.
    SettingsTable(const SettingsTable&) = delete;
    SettingsTable& operator=(const SettingsTable&) = delete;

    // In the settings file's order.
    std::span<const SettingsField<Settings>> fields() const { return fields_; }
    std::span<const OldPath> oldPaths() const { return oldPaths_; }

    const SettingsField<Settings>* find(std::string_view path) const
    {
        for (const SettingsField<Settings>& entry : fields_)
            if (entry.path == path)
                return &entry;
        return nullptr;
    }
    // Throws rhi::Error naming the path where no field has it.
    const SettingsField<Settings>& field(std::string_view path) const
    {
        if (const SettingsField<Settings>* entry = find(path))
            return *entry;
        detail::throwNoSuchField(path);
    }

    // The first field, in the table's order, whose value is outside its range or breaks its rule.
    std::optional<SettingsProblem> findProblem(const Settings& settings) const
    {
        for (const SettingsField<Settings>& entry : fields_) {
            std::optional<std::string> refused = detail::valueOutside(entry, entry.get(settings));
            if (!refused && entry.rule)
                refused = entry.rule(settings);
            if (refused)
                return SettingsProblem{std::string(entry.path), *refused + " is out of range", entry.allowed};
        }
        return std::nullopt;
    }
    // Throws rhi::Error "[<source>: ]<field>: <value> is out of range, allowed <allowed>" for findProblem's field.
    void validate(const Settings& settings, std::string_view source = {}) const
    {
        if (const std::optional<SettingsProblem> problem = findProblem(settings))
            detail::throwProblem(source, *problem);
    }

    // Reads the settings file's `json` over `settings`, which change only when the result validates; the paths the
    // file gave. Errors name `source`.
    std::vector<std::string_view> read(std::string_view json, std::string_view source, Settings& settings) const
    {
        Settings changed = settings;
        std::vector<std::string_view> given;
        detail::readSettingsJson(json, source, list_, oldPaths_,
                                 [&](const SettingsFieldInfo& info, const SettingValue& value) {
                                     static_cast<const SettingsField<Settings>&>(info).set(changed, value);
                                     given.push_back(info.path);
                                 });
        validate(changed, source);
        settings = changed;
        return given;
    }

    std::string toJson(const Settings& settings) const
    {
        return detail::writeSettingsJson(list_, [&settings](const SettingsFieldInfo& info) {
            return static_cast<const SettingsField<Settings>&>(info).get(settings);
        });
    }

    // The field at `path` as a settings file holds it (detail::settingValueText).
    std::string text(const Settings& settings, std::string_view path) const
    {
        const SettingsField<Settings>& entry = field(path);
        return detail::settingValueText(entry, entry.get(settings));
    }

    // Sets the field at `path` from its text as text() writes it ("close", "onChange", "2048"), as the command line
    // gives it. Throws rhi::Error "<path>: <what>, allowed <allowed>" for a value it does not take, or when the
    // settings are then refused; `settings` then keep their values.
    void set(Settings& settings, std::string_view path, std::string_view text) const
    {
        const SettingsField<Settings>& entry = field(path);
        constexpr std::string_view source = "settings";
        Settings changed = settings;
        entry.set(changed, detail::parseSettingText(entry, text, source));
        validate(changed, source);
        settings = changed;
    }

private:
    std::vector<SettingsField<Settings>> fields_;
    std::vector<OldPath> oldPaths_;
    detail::FieldList list_;
};

// The fields of `inner` as fields of the struct `Outer` whose member `member` (a generic lambda, as for field())
// holds an Inner; paths, ranges and rules unchanged.
template <typename Outer, typename Inner, typename Member>
std::vector<SettingsField<Outer>> nestedFields(const SettingsTable<Inner>& inner, Member member)
{
    std::vector<SettingsField<Outer>> fields;
    for (const SettingsField<Inner>& entry : inner.fields()) {
        SettingsField<Outer> outer;
        static_cast<SettingsFieldInfo&>(outer) = entry;
        outer.get = [get = entry.get, member](const Outer& s) { return get(member(s)); };
        outer.set = [set = entry.set, member](Outer& s, const SettingValue& value) { set(member(s), value); };
        if (entry.rule)
            outer.rule = [rule = entry.rule, member](const Outer& s) { return rule(member(s)); };
        fields.push_back(std::move(outer));
    }
    return fields;
}

} // namespace penumbra::settings
