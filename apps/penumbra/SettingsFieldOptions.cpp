#include "SettingsFieldOptions.hpp"

#include "penumbra/rhi/Error.hpp"

#include <cctype>
#include <fmt/format.h>

namespace penumbra::apps {
namespace {

using RenderSettingsField = settings::SettingsField<RenderSettings>;

std::string optionHelp(const RenderSettingsField& field)
{
    std::string summary(field.summary);
    summary[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(summary[0])));
    return fmt::format("The settings' {}, over the file's: {}; default {}. {}", field.path, field.allowed,
                       renderSettingsTable().text(RenderSettings{}, field.path), summary);
}

// The value's placeholder in the help: the path's last name in capitals ("PROJECTION").
std::string optionPlaceholder(const RenderSettingsField& field)
{
    std::string name(field.path.substr(field.path.rfind('.') + 1));
    for (char& c : name)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return name;
}

CLI::Validator fieldValidator(const RenderSettingsField& field)
{
    return CLI::Validator(
        [&field](std::string& text) {
            RenderSettings probe;
            try {
                renderSettingsTable().set(probe, field.path, text);
                return std::string();
            } catch (const rhi::Error&) {
                return field.range.kind == settings::SettingRangeKind::Listed
                           ? fmt::format("'{}' is not one of {}", text, field.allowed)
                           : fmt::format("'{}' is out of range, allowed {}", text, field.allowed);
            }
        },
        optionPlaceholder(field));
}

} // namespace

void addSettingsFieldOptions(CLI::App& command, SettingsFieldValues& values)
{
    for (const RenderSettingsField& field : renderSettingsTable().fields())
        if (!field.flag.empty())
            command
                .add_option_function<std::string>(
                    std::string(field.flag),
                    [&values, path = std::string(field.path)](const std::string& text) { values[path] = text; },
                    optionHelp(field))
                ->check(fieldValidator(field));
}

} // namespace penumbra::apps
