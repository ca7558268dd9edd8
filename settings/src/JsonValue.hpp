#pragma once

#include "penumbra/settings/SettingsField.hpp"

#include <nlohmann/json.hpp>
#include <string_view>

namespace penumbra::settings::detail {

// A field's value from its JSON; throws rhi::Error "<source>: <path>: <what>, allowed <allowed>" for a value of the
// wrong kind, a number beyond a float or an unknown name.
SettingValue settingValueFromJson(const nlohmann::json& value, const SettingsFieldInfo& field, std::string_view source);

// A field's value as a settings file holds it: floats as floats, names as strings.
nlohmann::ordered_json jsonOfSettingValue(const SettingsFieldInfo& field, const SettingValue& value);

} // namespace penumbra::settings::detail
