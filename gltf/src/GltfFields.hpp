#pragma once

#include "GltfDeviations.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::gltf {

using Json = nlohmann::json;

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

// What every check of a file's JSON shares: the file's name and root, for errors and index ranges.
struct JsonFile {
    std::string path;
    const Json& root;
    Deviations& deviations;

    // Throws GltfError "<path>: <pointer>: <what>".
    [[noreturn]] void fail(const std::string& pointer, std::string_view what) const;
    // How many elements the top-level array `name` has (0 when absent or not an array).
    std::size_t count(std::string_view name) const;
};

// A short rendering of a JSON value for "got ..." in an error.
std::string shortDump(const Json& value);

// One JSON object of a glTF file and its JSON pointer (RFC 6901): typed reads of its properties that
// refuse, naming the pointer of the offending value, what the glTF 2.0 JSON schema refuses (glTF 2.0
// specification, section 5, "Properties Reference"). Absent optional properties return nullopt.
class Fields {
public:
    // Checks that `value` is an object, and its common properties "name" (a string) and "extensions"
    // (an object of objects).
    Fields(const JsonFile& file, const Json& value, std::string pointer);

    const Json& json() const { return value_; }
    const std::string& pointer() const { return pointer_; }
    std::string pointerOf(std::string_view key) const;
    bool has(std::string_view key) const { return value_.contains(key); }
    [[noreturn]] void fail(std::string_view key, std::string_view what) const;

    // Fails when `key` is absent.
    void require(std::string_view key) const;
    std::optional<std::int64_t> integer(std::string_view key, std::int64_t low, std::int64_t high) const;
    // An index into the top-level array `array`.
    std::optional<int> index(std::string_view key, std::string_view array) const;
    // An array of unique indices into `array`, at least `minItems` of them.
    std::vector<int> indices(std::string_view key, std::string_view array, std::size_t minItems = 1) const;
    // A number in [low, high] (`exclusiveLow`: in (low, high]).
    std::optional<double> number(std::string_view key, double low, double high, bool exclusiveLow = false) const;
    // An array of exactly `size` numbers, each in [low, high].
    std::optional<std::vector<double>> numbers(std::string_view key, std::size_t size, double low = -kInfinity,
                                               double high = kInfinity) const;
    std::optional<bool> boolean(std::string_view key) const;
    std::optional<std::string> string(std::string_view key) const;
    std::optional<std::int64_t> oneOf(std::string_view key, std::initializer_list<std::int64_t> allowed) const;
    std::optional<std::string> oneOf(std::string_view key, std::initializer_list<std::string_view> allowed) const;
    std::optional<Fields> object(std::string_view key) const;
    // The objects of an array property, at least `minItems` of them.
    std::vector<Fields> objects(std::string_view key, std::size_t minItems = 1) const;
    // The extension object `name` under "extensions".
    std::optional<Fields> extension(std::string_view name) const;

private:
    const Json* member(std::string_view key) const;

    const JsonFile& file_;
    const Json& value_;
    std::string pointer_;
};

} // namespace penumbra::gltf
