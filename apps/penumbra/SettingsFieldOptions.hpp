#pragma once

#include "penumbra/shadows/ShadowSettings.hpp"

#include <CLI/CLI.hpp>

#include <functional>
#include <map>
#include <string>

namespace penumbra::apps {

// Shadow settings fields given on the command line, by field path ("directional.projection" -> "close").
using SettingsFieldValues = std::map<std::string, std::string, std::less<>>;

// An option for every shadow settings field that names one (shadows::ShadowSettingsField::flag: --projection,
// --static-maps, --realtime-casters), its help and its check written from the field's entry: what it does, the
// values it allows, its path and default. What is given lands in `values` by the field's path.
void addSettingsFieldOptions(CLI::App& command, SettingsFieldValues& values);

// Sets every field of `values` in `settings` (over the settings file's).
void applySettingsFieldValues(shadows::ShadowSettings& settings, const SettingsFieldValues& values);

} // namespace penumbra::apps
