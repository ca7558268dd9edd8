#pragma once
// Seeded mutations of glTF documents: one change each at a random place of the JSON, of the kinds a
// broken exporter or a hand edit makes (a value of another type, a deleted property, an index or a
// count off by some, a number out of range). For testing a loader against the Khronos glTF Validator.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace penumbra::testing {

struct GltfMutant {
    nlohmann::json document;
    std::string change; // e.g. "/nodes/3/scale: replaced by -1"
};

// `count` mutants of the documents in `bases`, taken in turn; the same seed gives the same mutants.
std::vector<GltfMutant> mutateGltf(const std::vector<nlohmann::json>& bases, std::size_t count, std::uint32_t seed);

} // namespace penumbra::testing
