#include "SettingsFieldOptions.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/ShadowSettingsJson.hpp"

#include <cctype>
#include <fmt/format.h>

namespace penumbra::apps {
namespace {

std::string help(const shadows::ShadowSettingsField& field)
{
    std::string summary(field.summary);
    summary[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(summary[0])));
    return fmt::format("The settings' {}, over the file's: {}; default {}. {}", field.path, field.allowed,
                       shadows::settingsFieldText(shadows::ShadowSettings{}, field.path), summary);
}

// The value's placeholder in the help: the path's last name in capitals ("PROJECTION").
std::string placeholder(const shadows::ShadowSettingsField& field)
{
    std::string name(field.path.substr(field.path.rfind('.') + 1));
    for (char& c : name)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return name;
}

CLI::Validator fieldValidator(const shadows::ShadowSettingsField& field)
{
    return CLI::Validator(
        [&field](std::string& text) {
            shadows::ShadowSettings probe;
            try {
                shadows::setSettingsField(probe, field.path, text);
                return std::string();
            } catch (const rhi::Error&) {
                return field.range.kind == shadows::SettingRangeKind::Listed
                           ? fmt::format("'{}' is not one of {}", text, field.allowed)
                           : fmt::format("'{}' is out of range, allowed {}", text, field.allowed);
            }
        },
        placeholder(field));
}

} // namespace

void addSettingsFieldOptions(CLI::App& command, SettingsFieldValues& values)
{
    for (const shadows::ShadowSettingsField& field : shadows::shadowSettingsFields())
        if (!field.flag.empty())
            command
                .add_option_function<std::string>(
                    std::string(field.flag),
                    [&values, path = std::string(field.path)](const std::string& text) { values[path] = text; },
                    help(field))
                ->check(fieldValidator(field));
}

void applySettingsFieldValues(shadows::ShadowSettings& settings, const SettingsFieldValues& values)
{
    for (const auto& [path, text] : values)
        shadows::setSettingsField(settings, path, text);
}

} // namespace penumbra::apps
