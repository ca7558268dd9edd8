#pragma once

#include "penumbra/shadows/ShadowSettings.hpp"

#include <filesystem>
#include <string>
#include <optional>
#include <string_view>

namespace penumbra::shadows {

// JSON form of ShadowSettings: the struct's field names, enums as lower-case strings
// ("pcf2x2".."pcf7x7", "hard"/"soft"/"dither", "d16"/"d24s8"/"d32f"), cascadeRatios as an array of 3.
// Missing fields keep their defaults; unknown fields, wrong types and out-of-range values throw
// rhi::Error "<sourceName>: <field>: <what>, allowed <range>".
ShadowSettings parseShadowSettings(std::string_view json, std::string_view sourceName);

// The static maps' modes by their JSON names ("everyFrame", "onChange", "onDemand"; "all", "dynamic"), which the
// command line takes too; nullopt for any other name.
std::optional<StaticShadowUpdate> parseStaticShadowUpdate(std::string_view name);
std::optional<RealtimeCasters> parseRealtimeCasters(std::string_view name);

// Every field, two-space indented; parseShadowSettings(toJson(s)) == s.
std::string toJson(const ShadowSettings& settings);

// The field at `path` (a shadowSettingsFields() path) of `settings` as a settings file holds it, floats at their
// shortest and names unquoted: "0.1", "[0.1, 0.25, 0.5]", "stable".
std::string settingsFieldText(const ShadowSettings& settings, std::string_view path);

// Sets the field at `path` from its text as settingsFieldText writes it ("close", "onChange", "2048"), as the
// tool's options give it. Throws rhi::Error "<path>: <what>, allowed <allowed>" for a value it does not take, or
// when the settings are then out of range.
void setSettingsField(ShadowSettings& settings, std::string_view path, std::string_view text);

ShadowSettings loadShadowSettings(const std::filesystem::path& path);

// Writes a temporary file beside `path` and renames it over `path`: the file is never half-written.
void saveShadowSettings(const std::filesystem::path& path, const ShadowSettings& settings);

} // namespace penumbra::shadows
