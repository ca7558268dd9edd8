#include "GltfFields.hpp"

#include "penumbra/gltf/GltfLoader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace penumbra::gltf {
namespace {

// RFC 6901, section 3: '~' and '/' in a key are written "~0" and "~1".
std::string escaped(std::string_view key)
{
    std::string out;
    for (const char c : key)
        out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    return out;
}

// A JSON number that is a whole number (glTF's "integer": JSON does not tell 1 from 1.0).
std::optional<double> wholeNumber(const Json& value)
{
    if (!value.is_number())
        return std::nullopt;
    const double number = value.get<double>();
    if (!std::isfinite(number) || std::floor(number) != number)
        return std::nullopt;
    return number;
}

std::string joined(std::initializer_list<std::string_view> words)
{
    std::string out;
    for (const std::string_view word : words)
        out += fmt::format("{}'{}'", out.empty() ? "" : ", ", word);
    return out;
}

} // namespace

void JsonFile::fail(const std::string& pointer, std::string_view what) const
{
    throw GltfError(fmt::format("{}: {}: {}", path, pointer.empty() ? "/" : pointer, what));
}

std::size_t JsonFile::count(std::string_view name) const
{
    const auto found = root.find(name);
    return found != root.end() && found->is_array() ? found->size() : 0;
}

std::string shortDump(const Json& value)
{
    constexpr std::size_t kLongest = 40;
    std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
    if (text.size() > kLongest)
        text = text.substr(0, kLongest - 3) + "...";
    return text;
}

Fields::Fields(const JsonFile& file, const Json& value, std::string pointer)
    : file_(file), value_(value), pointer_(std::move(pointer))
{
    if (!value_.is_object())
        file_.fail(pointer_, fmt::format("expected an object, got {}", shortDump(value_)));
    string("name");
    if (const Json* extensions = member("extensions")) {
        if (!extensions->is_object())
            fail("extensions", fmt::format("expected an object, got {}", shortDump(*extensions)));
        for (const auto& [name, extension] : extensions->items())
            if (!extension.is_object())
                file_.fail(pointerOf("extensions") + "/" + escaped(name),
                           fmt::format("expected an object, got {}", shortDump(extension)));
    }
}

std::string Fields::pointerOf(std::string_view key) const { return pointer_ + "/" + escaped(key); }

void Fields::fail(std::string_view key, std::string_view what) const { file_.fail(pointerOf(key), what); }

const Json* Fields::member(std::string_view key) const
{
    const auto found = value_.find(key);
    return found == value_.end() ? nullptr : &*found;
}

void Fields::require(std::string_view key) const
{
    if (!has(key))
        file_.fail(pointer_, fmt::format("the required property '{}' is missing", key));
}

std::optional<std::int64_t> Fields::integer(std::string_view key, std::int64_t low, std::int64_t high) const
{
    const Json* value = member(key);
    if (!value)
        return std::nullopt;
    const std::optional<double> number = wholeNumber(*value);
    // 2^63, the double nearest INT64_MAX, is not an int64: converting it would be undefined.
    if (!number || *number < double(low) || *number > double(high) || *number >= 0x1p63)
        fail(key, high == std::numeric_limits<std::int64_t>::max()
                      ? fmt::format("expected an integer of at least {}, got {}", low, shortDump(*value))
                      : fmt::format("expected an integer in [{}, {}], got {}", low, high, shortDump(*value)));
    return std::int64_t(*number);
}

std::optional<int> Fields::index(std::string_view key, std::string_view array) const
{
    const Json* value = member(key);
    if (!value)
        return std::nullopt;
    const std::size_t size = file_.count(array);
    const std::optional<double> number = wholeNumber(*value);
    if (!number || *number < 0 || *number >= double(size))
        fail(key, fmt::format("expected an index of {} (the file has {}), got {}", array, size, shortDump(*value)));
    return int(*number);
}

std::vector<int> Fields::indices(std::string_view key, std::string_view array, std::size_t minItems) const
{
    const Json* value = member(key);
    if (!value)
        return {};
    if (!value->is_array() || value->size() < minItems)
        fail(key,
             fmt::format("expected an array of at least {} indices of {}, got {}", minItems, array, shortDump(*value)));
    const std::size_t size = file_.count(array);
    std::vector<int> out;
    std::set<int> seen;
    for (std::size_t i = 0; i < value->size(); ++i) {
        const std::optional<double> number = wholeNumber((*value)[i]);
        const std::string at = fmt::format("{}/{}", pointerOf(key), i);
        if (!number || *number < 0 || *number >= double(size))
            file_.fail(at, fmt::format("expected an index of {} (the file has {}), got {}", array, size,
                                       shortDump((*value)[i])));
        if (!seen.insert(int(*number)).second)
            file_.fail(at, fmt::format("{} {} appears twice", array, int(*number)));
        out.push_back(int(*number));
    }
    return out;
}

std::optional<double> Fields::number(std::string_view key, double low, double high, bool exclusiveLow) const
{
    const Json* value = member(key);
    if (!value)
        return std::nullopt;
    const bool ok = value->is_number() && (exclusiveLow ? value->get<double>() > low : value->get<double>() >= low) &&
                    value->get<double>() <= high;
    if (!ok)
        fail(key, fmt::format("expected a number in {}{}, {}], got {}", exclusiveLow ? "(" : "[", low, high,
                              shortDump(*value)));
    return value->get<double>();
}

std::optional<std::vector<double>> Fields::numbers(std::string_view key, std::size_t size, double low,
                                                   double high) const
{
    const Json* value = member(key);
    if (!value)
        return std::nullopt;
    const bool ok = value->is_array() && value->size() == size &&
                    std::all_of(value->begin(), value->end(), [&](const Json& element) {
                        return element.is_number() && element.get<double>() >= low && element.get<double>() <= high;
                    });
    if (!ok)
        fail(key, std::isinf(low) && std::isinf(high)
                      ? fmt::format("expected an array of {} numbers, got {}", size, shortDump(*value))
                      : fmt::format("expected an array of {} numbers in [{}, {}], got {}", size, low, high,
                                    shortDump(*value)));
    return value->get<std::vector<double>>();
}

std::optional<bool> Fields::boolean(std::string_view key) const
{
    const Json* value = member(key);
    if (!value)
        return std::nullopt;
    if (!value->is_boolean())
        fail(key, fmt::format("expected true or false, got {}", shortDump(*value)));
    return value->get<bool>();
}

std::optional<std::string> Fields::string(std::string_view key) const
{
    const Json* value = member(key);
    if (!value)
        return std::nullopt;
    if (!value->is_string())
        fail(key, fmt::format("expected a string, got {}", shortDump(*value)));
    return value->get<std::string>();
}

std::optional<std::int64_t> Fields::oneOf(std::string_view key, std::initializer_list<std::int64_t> allowed) const
{
    const Json* value = member(key);
    if (!value)
        return std::nullopt;
    // Compared as doubles: a number beyond int64 (8.9e35, found by the gltf fuzz target) is no allowed value, and
    // converting it to int64 first would be undefined.
    const std::optional<double> number = wholeNumber(*value);
    const auto match = std::find_if(allowed.begin(), allowed.end(),
                                    [&](std::int64_t candidate) { return number && double(candidate) == *number; });
    if (match == allowed.end())
        fail(key, fmt::format("expected one of {}, got {}", fmt::join(allowed, ", "), shortDump(*value)));
    return *match;
}

std::optional<std::string> Fields::oneOf(std::string_view key, std::initializer_list<std::string_view> allowed) const
{
    const Json* value = member(key);
    if (!value)
        return std::nullopt;
    if (!value->is_string() || std::find(allowed.begin(), allowed.end(), value->get<std::string>()) == allowed.end())
        fail(key, fmt::format("expected one of {}, got {}", joined(allowed), shortDump(*value)));
    return value->get<std::string>();
}

std::optional<Fields> Fields::object(std::string_view key) const
{
    const Json* value = member(key);
    if (!value)
        return std::nullopt;
    return Fields(file_, *value, pointerOf(key));
}

std::vector<Fields> Fields::objects(std::string_view key, std::size_t minItems) const
{
    const Json* value = member(key);
    if (!value)
        return {};
    if (!value->is_array() || value->size() < minItems)
        fail(key, fmt::format("expected an array of at least {} objects, got {}", minItems, shortDump(*value)));
    std::vector<Fields> out;
    for (std::size_t i = 0; i < value->size(); ++i)
        out.emplace_back(file_, (*value)[i], fmt::format("{}/{}", pointerOf(key), i));
    return out;
}

std::optional<Fields> Fields::extension(std::string_view name) const
{
    const Json* extensions = member("extensions");
    if (!extensions || !extensions->contains(name))
        return std::nullopt;
    return Fields(file_, (*extensions)[std::string(name)], pointerOf("extensions") + "/" + escaped(name));
}

} // namespace penumbra::gltf
