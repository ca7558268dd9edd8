#include "penumbra/settings/SettingRange.hpp"

#include <cmath>
#include <cstdint>
#include <fmt/format.h>

namespace penumbra::settings {

bool withinRange(const SettingRange& range, double value)
{
    // As floats: a float field at a bound (0.0001f) is within it, as its float check always had it.
    const float v = static_cast<float>(value);
    switch (range.kind) {
    case SettingRangeKind::Listed:
        return true;
    case SettingRangeKind::Closed:
        return v >= static_cast<float>(range.low) && v <= static_cast<float>(range.high);
    case SettingRangeKind::Above:
        return v > static_cast<float>(range.low);
    case SettingRangeKind::AtLeast:
        return std::isfinite(v) && v >= static_cast<float>(range.low);
    case SettingRangeKind::PowersOfTwo: {
        if (!(value >= range.low && value <= range.high))
            return false;
        const auto whole = static_cast<std::uint64_t>(value);
        return static_cast<double>(whole) == value && (whole & (whole - 1)) == 0;
    }
    }
    return false;
}

std::string rangeText(const SettingRange& range)
{
    switch (range.kind) {
    case SettingRangeKind::Closed:
        return fmt::format("{}..{}", range.low, range.high);
    case SettingRangeKind::PowersOfTwo:
        return fmt::format("powers of two {}..{}", range.low, range.high);
    case SettingRangeKind::Above:
        return fmt::format("> {}", range.low);
    case SettingRangeKind::AtLeast:
        return fmt::format("at least {}", range.low);
    case SettingRangeKind::Listed:
        break;
    }
    return "";
}

} // namespace penumbra::settings
