// penumbra settings: the default settings file, or with --markdown the settings reference (docs/settings.md), both
// printed from the code's own declarations so that the reference cannot drift from what the parsers accept.
#include "Commands.hpp"
#include "EnvironmentOption.hpp"
#include "RenderSettings.hpp"

#include "penumbra/shadows/ShadowSettingsJson.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <memory>
#include <string>

namespace penumbra::apps {
namespace {

std::string vec3Text(const glm::vec3& v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

void printMarkdown()
{
    fmt::print("| field | default | allowed | what it does |\n| --- | --- | --- | --- |\n");
    for (const shadows::ShadowSettingsField& field : shadows::shadowSettingsFields())
        fmt::print("| `{}` | `{}` | {} | {} |\n", field.path,
                   shadows::settingsFieldText(shadows::ShadowSettings{}, field.path), field.allowed, field.summary);
    const render::FrameDesc frame;
    const render::AmbientLight ambient;
    fmt::print(
        "\nThe tool's `--settings` file may also hold (`apps/penumbra/RenderSettings.hpp`; the command line's flags "
        "win over them):\n\n");
    fmt::print("| field | default | allowed | what it does |\n| --- | --- | --- | --- |\n");
    fmt::print("| `ambient.color` | `{}` | 3 numbers, each at least 0 | linear colour of the ambient light (the sky's "
               "with `ground`) |\n",
               vec3Text(ambient.color));
    fmt::print("| `ambient.intensity` | `{}` | 0..{} | the colour's multiplier |\n", ambient.intensity,
               render::kMaxAmbientIntensity);
    fmt::print("| `ambient.ground` | none | 3 numbers, each at least 0 | linear colour from below: a sky/ground "
               "hemisphere |\n");
    const EnvironmentSetting environment;
    fmt::print("| `environment.source` | `{}` | {} | image-based lighting (docs/lighting.md): an equirectangular file, "
               "the built-in studio, none (the ambient light instead), or auto (the studio for glTF files) |\n",
               environment.source, kEnvironmentSyntax);
    fmt::print("| `environment.intensity` | `{}` | 0..{} | the environment's multiplier |\n", environment.intensity,
               render::kMaxEnvironmentIntensity);
    fmt::print("| `environment.rotation` | `{}` | -360..360 | degrees the environment turns about +y |\n",
               environment.rotation);
    fmt::print("| `anisotropy` | `{}` | 1 (off)..{} | most anisotropic filtering of textures, lowered to the "
               "device's limit |\n",
               frame.maxAnisotropy, kMaxAnisotropyOption);
    fmt::print("| `msaa` | `{}` | {} | samples per pixel of the depth prepass and the lit pass |\n", frame.msaa,
               fmt::join(kMsaaCounts, ", "));
    fmt::print("| `shadowPath` | `{}` | {} | where directional shadows are evaluated |\n",
               kShadowPathNames[static_cast<std::size_t>(frame.shadowPath)], fmt::join(kShadowPathNames, ", "));
}

} // namespace

void addSettingsCommand(CLI::App& app)
{
    auto* command =
        app.add_subcommand("settings",
                           "Print the default shadow settings as a --settings file, or the reference table");
    auto markdown = std::make_shared<bool>(false);
    command->add_flag("--markdown", *markdown,
                      "Print every settings field with its default and allowed values, as Markdown");
    command->callback([markdown] {
        if (*markdown)
            printMarkdown();
        else
            fmt::print("{}", shadows::toJson(shadows::ShadowSettings{}));
    });
}

} // namespace penumbra::apps
