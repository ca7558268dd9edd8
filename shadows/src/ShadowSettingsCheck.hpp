#pragma once

#include "penumbra/shadows/ShadowSettings.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace penumbra::shadows::detail {

// One field out of range: "<field>: <what>, allowed <allowed>".
struct SettingsProblem {
    std::string field;
    std::string what;
    std::string allowed;
};

// The allowed values of a field path ("directional.cascadeCount"), as messages state them.
std::string_view allowedValues(std::string_view field);

std::optional<SettingsProblem> findSettingsProblem(const ShadowSettings& settings);

} // namespace penumbra::shadows::detail
