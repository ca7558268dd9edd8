#pragma once

#include <string>

namespace penumbra::settings {

// How a settings field's numbers are bounded: by the values or names it lists (enums, sample counts), a closed range
// low..high, the powers of two in low..high, anything above low, or anything finite from low up.
enum class SettingRangeKind { Listed, Closed, PowersOfTwo, Above, AtLeast };
struct SettingRange {
    SettingRangeKind kind = SettingRangeKind::Listed;
    double low = 0.0;
    double high = 0.0;
};

// Whether `value` is in the range, compared as the float fields hold it; NaN never is. A Listed range leaves the
// check to the field's list (true).
bool withinRange(const SettingRange& range, double value);

// The range as messages, help and docs state it: "0.001..1", "powers of two 256..8192", "> 0.001", "at least 0";
// empty for Listed.
std::string rangeText(const SettingRange& range);

} // namespace penumbra::settings
