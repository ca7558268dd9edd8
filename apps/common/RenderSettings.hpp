#pragma once

#include "penumbra/render/AmbientLight.hpp"
#include "penumbra/render/SceneRenderer.hpp"
#include "penumbra/settings/SettingsTable.hpp"
#include "penumbra/shadows/ShadowSettings.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::apps {

// The settings' "environment" object: render::EnvironmentLight before its image is read (environmentOf).
struct EnvironmentSetting {
    std::string source = "auto"; // kEnvironmentSyntax; a relative file is read from the working directory
    float intensity = 1.0f;
    float rotation = 0.0f; // degrees about +y
};

// What a --settings file holds: the shadow settings' fields at its top level (shadows::shadowSettingsTable) beside
// the frame's render-level settings (render::FrameDesc's ambient light, environment, anisotropy, MSAA and shadow
// path). Each field is declared once, in renderSettingsTable() (RenderSettingsTable.cpp); the command line's flags
// win over the file, the file over these defaults.
struct RenderSettings {
    shadows::ShadowSettings shadows;
    render::AmbientLight ambient;
    EnvironmentSetting environment;
    float anisotropy = render::FrameDesc{}.maxAnisotropy;
    std::uint32_t msaa = render::FrameDesc{}.msaa;
    render::ShadowPath shadowPath = render::FrameDesc{}.shadowPath;
};

// Every field of a --settings file: the render-level ones, then the shadow settings' (paths unchanged).
const settings::SettingsTable<RenderSettings>& renderSettingsTable();
// Whether a field of renderSettingsTable() is render-level (not a shadow setting).
bool isRenderLevelField(std::string_view path);

// The shadow path's name in the settings ("forward", "screenSpace"), as its field names it.
std::string_view shadowPathName(render::ShadowPath path);

// Reads a --settings file over `settings`; the paths it gave. Throws rhi::Error "<file>: <field>: <what>" for an
// unreadable file, bad JSON, an unknown field or a value out of range.
std::vector<std::string_view> loadRenderSettings(const std::filesystem::path& path, RenderSettings& settings);

// Settings fields given on the command line, by field path ("directional.projection" -> "close").
using SettingsFieldValues = std::map<std::string, std::string, std::less<>>;

// Sets every field of `values` in `settings` (over the settings file's); throws rhi::Error naming the field.
void applySettingsFieldValues(RenderSettings& settings, const SettingsFieldValues& values);

} // namespace penumbra::apps
