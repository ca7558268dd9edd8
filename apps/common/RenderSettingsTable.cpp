// The render settings' table: each render-level field of a --settings file declared once (path, range, allowed
// values, summary, option), beside the shadow settings' fields; validation, the settings file, the tool's options,
// the viewer's controls and docs/settings.md follow from it (penumbra/settings/SettingsTable.hpp).
#include "RenderSettings.hpp"

#include "EnvironmentOption.hpp"

#include <filesystem>
#include <fmt/format.h>

namespace penumbra::apps {
namespace {

using settings::nameOf;
using settings::SettingRange;
using settings::SettingRangeKind;

// 16: what Vulkan requires of devices with samplerAnisotropy (the specification's Required Limits table,
// maxSamplerAnisotropy) and more than GPUs offer.
constexpr double kMaxAnisotropyOption = 16.0;

// A linear colour's components.
constexpr SettingRange kColorComponent{SettingRangeKind::AtLeast, 0.0};

// kEnvironmentSyntax: an .hdr or .exr file or one of the names.
std::optional<std::string> environmentSourceKnown(const RenderSettings& s)
{
    const std::string& source = s.environment.source;
    const std::string extension = std::filesystem::path(source).extension().string();
    if (source == "default" || source == "none" || source == "auto" || extension == ".hdr" || extension == ".exr")
        return std::nullopt;
    return fmt::format("\"{}\"", source);
}

std::vector<settings::SettingsField<RenderSettings>> renderLevelFields()
{
    const std::string colorAllowed = fmt::format("3 numbers, each {}", settings::rangeText(kColorComponent));
    return {
        settings::field<RenderSettings>(
            "ambient.color", kColorComponent, colorAllowed,
            "linear colour of the ambient light (the sky's with `ground`)",
            [](auto& s) -> auto& { return s.ambient.color; }),
        settings::numeric<RenderSettings>(
            "ambient.intensity", {SettingRangeKind::Closed, 0.0, render::kMaxAmbientIntensity},
            "the colour's multiplier", [](auto& s) -> auto& { return s.ambient.intensity; }),
        settings::field<RenderSettings>(
            "ambient.ground", kColorComponent, colorAllowed, "linear colour from below: a sky/ground hemisphere",
            [](auto& s) -> auto& { return s.ambient.ground; }),
        settings::withRule(
            settings::field<RenderSettings>(
                "environment.source", {}, kEnvironmentSyntax,
                "image-based lighting (docs/lighting.md): an equirectangular file, the built-in studio, none (the "
                "ambient light instead), or auto (the studio for glTF files without an ambient light given)",
                [](auto& s) -> auto& { return s.environment.source; }, "--environment"),
            environmentSourceKnown),
        settings::numeric<RenderSettings>(
            "environment.intensity", {SettingRangeKind::Closed, 0.0, render::kMaxEnvironmentIntensity},
            "the environment's multiplier", [](auto& s) -> auto& { return s.environment.intensity; },
            "--environment-intensity"),
        settings::numeric<RenderSettings>(
            "environment.rotation", {SettingRangeKind::Closed, -360.0, 360.0}, "degrees the environment turns about +y",
            [](auto& s) -> auto& { return s.environment.rotation; }, "--environment-rotation"),
        settings::numeric<RenderSettings>(
            "anisotropy", {SettingRangeKind::Closed, 1.0, kMaxAnisotropyOption},
            "most anisotropic filtering of textures (1: off), lowered to the device's limit",
            [](auto& s) -> auto& { return s.anisotropy; }, "--anisotropy"),
        settings::listed<RenderSettings>(
            "msaa", {1, 2, 4, 8},
            "samples per pixel of the depth prepass and the lit pass (1: off), as the device offers them",
            [](auto& s) -> auto& { return s.msaa; }, "--msaa"),
        settings::named<RenderSettings>(
            "shadowPath",
            {nameOf(render::ShadowPath::Forward, "forward"), nameOf(render::ShadowPath::ScreenSpace, "screenSpace")},
            "where directional shadows are evaluated: forward (in the lit pass) or screenSpace (collected after the "
            "depth prepass into a screen-space shadow texture that the lit pass reads; needs the prepass)",
            [](auto& s) -> auto& { return s.shadowPath; }, "--shadow-path"),
    };
}

std::vector<settings::SettingsField<RenderSettings>> renderTableFields()
{
    std::vector<settings::SettingsField<RenderSettings>> fields = renderLevelFields();
    for (settings::SettingsField<RenderSettings>& shadowField : settings::nestedFields<RenderSettings>(
             shadows::shadowSettingsTable(), [](auto& s) -> auto& { return s.shadows; }))
        fields.push_back(std::move(shadowField));
    return fields;
}

} // namespace

const settings::SettingsTable<RenderSettings>& renderSettingsTable()
{
    const std::span<const settings::OldPath> oldPaths = shadows::shadowSettingsTable().oldPaths();
    static const settings::SettingsTable<RenderSettings> table(renderTableFields(),
                                                               std::vector<settings::OldPath>(oldPaths.begin(),
                                                                                              oldPaths.end()));
    return table;
}

} // namespace penumbra::apps
