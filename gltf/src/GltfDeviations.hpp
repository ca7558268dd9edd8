#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace penumbra::gltf {

// What the Khronos glTF Validator reports as an error but the loader accepts, because what is drawn
// does not depend on it (the README lists them): accessor min/max that do not match the elements (or
// are missing on POSITION; the loader computes bounds itself), non-unit normals and tangents (the
// shaders normalize). Each kind becomes one note per file, naming where it first occurs.
class Deviations {
public:
    void add(std::string_view kind, const std::string& pointer);
    // "tolerated: <kind> at <pointer> (and N more)", a line per kind.
    std::vector<std::string> notes() const;

private:
    std::map<std::string, std::pair<std::string, std::size_t>, std::less<>> kinds_; // kind -> first pointer, count
};

inline constexpr std::string_view kMinMaxMismatch = "accessor min/max do not match its elements";
inline constexpr std::string_view kMissingBounds = "POSITION accessor without min/max";
inline constexpr std::string_view kNonUnit = "normals or tangents not unit length (normalized when shaded)";

// The Khronos glTF Validator's tolerance for a unit vector or quaternion (gltf-validator, ACCESSOR_NON_UNIT and
// ROTATION_NON_UNIT): |length - 1| above it is not unit length.
inline constexpr double kUnitLengthTolerance = 5e-4;

// How far a node matrix's last row may be from (0, 0, 0, 1), float rounding in a writer, before it is refused as not
// a matrix of translation, rotation and scale; within it the row is read as (0, 0, 0, 1).
inline constexpr double kAffineRowTolerance = 1e-6;

} // namespace penumbra::gltf
