#pragma once

#include "RenderSettings.hpp"

#include <CLI/CLI.hpp>

namespace penumbra::apps {

// An option for every settings field that names one (settings::SettingsFieldInfo::flag: --projection, --anisotropy,
// --msaa, --shadow-path, --environment, ...), its help and its check written from the field's entry in
// renderSettingsTable(): what it does, the values it allows, its path and default. What is given lands in `values` by
// the field's path (applySettingsFieldValues sets it over a settings file's).
void addSettingsFieldOptions(CLI::App& command, SettingsFieldValues& values);

} // namespace penumbra::apps
