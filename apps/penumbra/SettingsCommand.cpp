// penumbra settings: the default settings file (shadow and render-level fields), or with --markdown the settings
// reference (docs/settings.md), both printed from the code's own declarations so that the reference cannot drift from
// what the parsers accept.
#include "Commands.hpp"
#include "RenderSettings.hpp"

#include "penumbra/shadows/ShadowSettingsJson.hpp"

#include <fmt/format.h>
#include <memory>
#include <string>

namespace penumbra::apps {
namespace {

// One row per field: its path, its default, the values it allows and what it does.
template <typename Settings>
void printFieldRows(const settings::SettingsTable<Settings>& table, bool (*listed)(std::string_view path))
{
    fmt::print("| field | default | allowed | what it does |\n| --- | --- | --- | --- |\n");
    for (const settings::SettingsField<Settings>& field : table.fields())
        if (listed(field.path))
            fmt::print("| `{}` | `{}` | {} | {} |\n", field.path, table.text(Settings{}, field.path), field.allowed,
                       field.summary);
}

void printMarkdown()
{
    printFieldRows(shadows::shadowSettingsTable(), [](std::string_view) { return true; });
    fmt::print(
        "\nThe tool's `--settings` file may also hold (`apps/common/RenderSettings.hpp`; the command line's flags "
        "win over them):\n\n");
    printFieldRows(renderSettingsTable(), isRenderLevelField);
}

} // namespace

void addSettingsCommand(CLI::App& app)
{
    auto* command =
        app.add_subcommand("settings",
                           "Print the default settings (shadow and render-level) as a --settings file, or the "
                           "reference table");
    auto markdown = std::make_shared<bool>(false);
    command->add_flag("--markdown", *markdown,
                      "Print every settings field with its default and allowed values, as Markdown");
    command->callback([markdown] {
        if (*markdown)
            printMarkdown();
        else
            fmt::print("{}", renderSettingsTable().toJson(RenderSettings{}));
    });
}

} // namespace penumbra::apps
