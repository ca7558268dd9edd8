#include "GltfMutations.hpp"

#include <array>
#include <random>

namespace penumbra::testing {
namespace {

using Json = nlohmann::json;

void collectPointers(const Json& value, const Json::json_pointer& at, std::vector<Json::json_pointer>& out)
{
    if (!at.empty())
        out.push_back(at);
    if (value.is_object())
        for (const auto& [key, child] : value.items())
            collectPointers(child, at / key, out);
    else if (value.is_array())
        for (std::size_t i = 0; i < value.size(); ++i)
            collectPointers(value[i], at / i, out);
}

// Values of every JSON type, and numbers a loader must bound: negative, fractional, past 2^31.
Json replacement(std::mt19937& random)
{
    const std::array<Json, 12> values{
        -1, 0, 1, 2.5, 1e9, 2147483648.0, "text", true, nullptr, Json::array(), Json::object(), Json::array({1, 2, 3})};
    return values[std::uniform_int_distribution<std::size_t>(0, values.size() - 1)(random)];
}

// A change that keeps the value's type: an integer off by some, a number scaled, an array shortened
// or lengthened, a string replaced.
std::string tweak(Json& value, std::mt19937& random)
{
    const int pick = std::uniform_int_distribution<int>(0, 3)(random);
    if (value.is_number_integer()) {
        const std::array<std::int64_t, 4> deltas{1, -1, 7, 65536};
        value = value.get<std::int64_t>() + deltas[std::size_t(pick)];
        return "changed by " + std::to_string(deltas[std::size_t(pick)]);
    }
    if (value.is_number()) {
        const std::array<double, 4> factors{-1.0, 10.0, 0.5, 1e6};
        value = value.get<double>() * factors[std::size_t(pick)];
        return "scaled by " + Json(factors[std::size_t(pick)]).dump();
    }
    if (value.is_array() && !value.empty()) {
        if (pick % 2 == 0) {
            value.erase(value.size() - 1);
            return "last element removed";
        }
        value.push_back(value.back());
        return "last element repeated";
    }
    if (value.is_string()) {
        value = pick % 2 == 0 ? "" : "BOGUS";
        return "string replaced";
    }
    value = replacement(random);
    return "replaced by " + value.dump();
}

} // namespace

std::vector<GltfMutant> mutateGltf(const std::vector<nlohmann::json>& bases, std::size_t count, std::uint32_t seed)
{
    std::mt19937 random(seed);
    std::vector<GltfMutant> mutants;
    for (std::size_t i = 0; i < count; ++i) {
        GltfMutant mutant{bases[i % bases.size()], {}};
        std::vector<Json::json_pointer> pointers;
        collectPointers(mutant.document, Json::json_pointer(), pointers);
        const Json::json_pointer at =
            pointers[std::uniform_int_distribution<std::size_t>(0, pointers.size() - 1)(random)];
        Json& value = mutant.document[at];
        std::string change;
        switch (std::uniform_int_distribution<int>(0, 2)(random)) {
        case 0:
            value = replacement(random);
            change = "replaced by " + value.dump();
            break;
        case 1:
            if (mutant.document[at.parent_pointer()].is_object()) {
                mutant.document[at.parent_pointer()].erase(at.back());
                change = "deleted";
                break;
            }
            [[fallthrough]];
        default:
            change = tweak(value, random);
            break;
        }
        mutant.change = at.to_string() + ": " + change;
        mutants.push_back(std::move(mutant));
    }
    return mutants;
}

} // namespace penumbra::testing
