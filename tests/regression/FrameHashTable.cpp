#include "FrameHashTable.hpp"

#include "penumbra/rhi/AtomicFile.hpp"
#include "penumbra/rhi/Error.hpp"

#include <charconv>
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace penumbra::testing {
namespace {

using Json = nlohmann::json;

constexpr std::string_view kFormat = "penumbra frame hashes";

std::string hex(std::uint64_t hash) { return fmt::format("{:016x}", hash); }

const Json& field(const Json& object, const std::filesystem::path& path, const std::string& pointer)
{
    const Json::json_pointer at(pointer);
    if (!object.contains(at))
        throw rhi::Error(fmt::format("{}: {}: missing", path.string(), pointer));
    return object.at(at);
}

std::string stringField(const Json& object, const std::filesystem::path& path, const std::string& pointer)
{
    const Json& value = field(object, path, pointer);
    if (!value.is_string())
        throw rhi::Error(fmt::format("{}: {}: expected a string, got {}", path.string(), pointer, value.dump()));
    return value.get<std::string>();
}

} // namespace

std::uint64_t fnv1a(const void* bytes, std::size_t size)
{
    constexpr std::uint64_t kOffsetBasis = 0xcbf29ce484222325ull;
    constexpr std::uint64_t kPrime = 0x100000001b3ull;
    std::uint64_t hash = kOffsetBasis;
    const auto* p = static_cast<const unsigned char*>(bytes);
    for (std::size_t i = 0; i < size; ++i)
        hash = (hash ^ p[i]) * kPrime;
    return hash;
}

std::uint64_t hashOf(const rhi::Image& image) { return fnv1a(image.bytes.data(), image.bytes.size()); }

std::uint64_t hashOf(const rhi::DepthImage& depth)
{
    return fnv1a(depth.depth.data(), depth.depth.size() * sizeof(float));
}

FrameHashFile readFrameHashes(const std::filesystem::path& path)
{
    std::ifstream in(path);
    if (!in)
        throw rhi::Error(fmt::format("{}: cannot open the frame hash table", path.string()));
    std::stringstream text;
    text << in.rdbuf();
    const Json json = Json::parse(text.str(), nullptr, false);
    if (json.is_discarded())
        throw rhi::Error(fmt::format("{}: not valid JSON", path.string()));
    if (stringField(json, path, "/format") != kFormat)
        throw rhi::Error(fmt::format("{}: /format: expected \"{}\"", path.string(), kFormat));
    FrameHashFile file{stringField(json, path, "/configuration"), stringField(json, path, "/driver"), {}};
    const Json& frames = field(json, path, "/frames");
    if (!frames.is_object())
        throw rhi::Error(fmt::format("{}: /frames: expected an object", path.string()));
    for (const auto& [frame, outputs] : frames.items()) {
        if (!outputs.is_object())
            throw rhi::Error(fmt::format("{}: /frames/{}: expected an object", path.string(), frame));
        for (const auto& [output, value] : outputs.items()) {
            const std::string pointer = fmt::format("/frames/{}/{}", frame, output);
            std::uint64_t hash = 0;
            const std::string digits = value.is_string() ? value.get<std::string>() : std::string();
            const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), hash, 16);
            if (digits.size() != 16 || error != std::errc() || end != digits.data() + digits.size())
                throw rhi::Error(
                    fmt::format("{}: {}: expected 16 hex digits, got {}", path.string(), pointer, value.dump()));
            file.frames[frame][output] = hash;
        }
    }
    return file;
}

void writeFrameHashes(const std::filesystem::path& path, const FrameHashFile& file)
{
    nlohmann::ordered_json frames = nlohmann::ordered_json::object();
    for (const auto& [frame, outputs] : file.frames)
        for (const auto& [output, hash] : outputs)
            frames[frame][output] = hex(hash);
    const nlohmann::ordered_json json{{"format", kFormat},
                                      {"configuration", file.configuration},
                                      {"driver", file.driver},
                                      {"frames", frames}};
    rhi::writeFileAtomically(path, json.dump(2) + "\n");
}

std::vector<std::string> frameDifferences(const FrameTable& table, const FrameTable& rendered)
{
    std::vector<std::string> differences;
    for (const auto& [frame, outputs] : rendered) {
        const auto kept = table.find(frame);
        if (kept == table.end()) {
            differences.push_back(frame + ": not in the table");
            continue;
        }
        for (const auto& [output, hash] : outputs) {
            const auto old = kept->second.find(output);
            if (old == kept->second.end())
                differences.push_back(fmt::format("{}: {} is not in the table", frame, output));
            else if (old->second != hash)
                differences.push_back(
                    fmt::format("{}: {} is {} but the table has {}", frame, output, hex(hash), hex(old->second)));
        }
        for (const auto& [output, hash] : kept->second)
            if (!outputs.contains(output))
                differences.push_back(
                    fmt::format("{}: the table has {}, which the frame no longer writes", frame, output));
    }
    for (const auto& [frame, outputs] : table)
        if (!rendered.contains(frame))
            differences.push_back(frame + ": in the table but no longer rendered");
    return differences;
}

} // namespace penumbra::testing
