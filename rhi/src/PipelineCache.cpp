#include "penumbra/rhi/PipelineCache.hpp"

#include "penumbra/rhi/AtomicFile.hpp"
#include "penumbra/rhi/Error.hpp"

#include <array>
#include <cstdlib>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <iterator>

namespace penumbra::rhi {
namespace {

// An entry file: this header, then the identity, the key and the payload, integers in the machine's byte order
// (the identity names the machine's driver anyway).
constexpr std::array<char, 8> kMagic{'P', 'N', 'B', 'C', 'A', 'C', 'H', 'E'};
constexpr std::uint32_t kFormatVersion = 1;
struct Header {
    std::array<char, 8> magic;
    std::uint32_t version;
    std::uint32_t identityBytes;
    std::uint32_t keyBytes;
    std::uint32_t unused;
    std::uint64_t payloadBytes;
    std::uint64_t checksum; // of identity, key and payload
};
static_assert(sizeof(Header) == 40);

// FNV-1a, 64 bits (Fowler, Noll, Vo; IETF draft-eastlake-fnv, section 2): a checksum against torn or damaged
// files and a file name, never a proof of identity: load() compares the identity and key themselves.
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash = 14695981039346656037ull)
{
    for (const char c : bytes)
        hash = (hash ^ std::uint8_t(c)) * 1099511628211ull;
    return hash;
}

std::uint64_t checksum(std::string_view identity, std::string_view key, std::string_view payload)
{
    return fnv1a(payload, fnv1a(key, fnv1a(identity)));
}

std::optional<std::string> readWholeFile(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return std::nullopt;
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Why `bytes` is not a valid entry for (identity, key); empty when it is.
std::string refusal(std::string_view bytes, std::string_view identity, std::string_view key)
{
    Header header{};
    if (bytes.size() < sizeof(Header))
        return fmt::format("truncated: {} bytes, shorter than the {}-byte header", bytes.size(), sizeof(Header));
    std::memcpy(&header, bytes.data(), sizeof(Header));
    if (header.magic != kMagic)
        return "not a Penumbra cache file";
    if (header.version != kFormatVersion)
        return fmt::format("format version {}, this build reads {}", header.version, kFormatVersion);
    const std::uint64_t expected =
        sizeof(Header) + std::uint64_t(header.identityBytes) + header.keyBytes + header.payloadBytes;
    if (bytes.size() < expected)
        return fmt::format("truncated: {} bytes, its header says {}", bytes.size(), expected);
    if (bytes.size() > expected)
        return fmt::format("corrupt: {} bytes, its header says {}", bytes.size(), expected);
    const std::string_view theirIdentity = bytes.substr(sizeof(Header), header.identityBytes);
    const std::string_view theirKey = bytes.substr(sizeof(Header) + header.identityBytes, header.keyBytes);
    const std::string_view payload = bytes.substr(sizeof(Header) + header.identityBytes + header.keyBytes);
    if (checksum(theirIdentity, theirKey, payload) != header.checksum)
        return "corrupt: the checksum does not match";
    if (theirIdentity != identity)
        return fmt::format("foreign: written for '{}', this is '{}'", theirIdentity, identity);
    if (theirKey != key)
        return "written for another key with the same hash";
    return {};
}

} // namespace

std::filesystem::path defaultPipelineCacheFolder()
{
    // The specification: "If $XDG_CACHE_HOME is either not set or empty, a default equal to $HOME/.cache should be
    // used", and relative paths in these variables are invalid and ignored.
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && std::filesystem::path(xdg).is_absolute())
        return std::filesystem::path(xdg) / "penumbra";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "penumbra";
    return {};
}

PipelineCache::PipelineCache(std::filesystem::path folder) : folder_(std::move(folder))
{
    if (folder_.empty())
        throw Error("PipelineCache: the folder is empty");
}

std::filesystem::path PipelineCache::entryPath(std::string_view kind, std::string_view identity,
                                               std::string_view key) const
{
    return folder_ / fmt::format("{}-{:016x}.bin", kind, fnv1a(key, fnv1a(identity)));
}

std::optional<std::string> PipelineCache::load(std::string_view kind, std::string_view identity, std::string_view key)
{
    const std::filesystem::path path = entryPath(kind, identity, key);
    std::optional<std::string> bytes = readWholeFile(path);
    std::string why = bytes ? refusal(*bytes, identity, key) : std::string();
    const std::lock_guard lock(mutex_);
    PipelineCacheCounts& counts = counts_[std::string(kind)];
    if (!bytes) {
        ++counts.missed;
        return std::nullopt;
    }
    if (!why.empty()) {
        ++counts.missed;
        ++counts.ignored;
        notes_.push_back(fmt::format("ignored {}: {}", path.string(), why));
        return std::nullopt;
    }
    ++counts.loaded;
    return bytes->substr(sizeof(Header) + identity.size() + key.size());
}

void PipelineCache::store(std::string_view kind, std::string_view identity, std::string_view key,
                          std::string_view payload, double compileMs)
{
    Header header{kMagic, kFormatVersion, std::uint32_t(identity.size()),  std::uint32_t(key.size()),
                  0,      payload.size(), checksum(identity, key, payload)};
    std::string bytes(sizeof(Header), '\0');
    std::memcpy(bytes.data(), &header, sizeof(Header));
    bytes.append(identity).append(key).append(payload);
    std::string failure;
    try {
        writeFileAtomically(entryPath(kind, identity, key), bytes);
    } catch (const Error& e) {
        failure = fmt::format("not stored: {}", e.what());
    }
    const std::lock_guard lock(mutex_);
    PipelineCacheCounts& counts = counts_[std::string(kind)];
    counts.compileMs += compileMs;
    if (failure.empty())
        ++counts.stored;
    else
        notes_.push_back(std::move(failure));
}

void PipelineCache::refuse(std::string_view kind, std::string_view identity, std::string_view key, std::string_view why)
{
    const std::lock_guard lock(mutex_);
    PipelineCacheCounts& counts = counts_[std::string(kind)];
    if (counts.loaded > 0)
        --counts.loaded;
    ++counts.missed;
    ++counts.ignored;
    notes_.push_back(fmt::format("ignored {}: {}", entryPath(kind, identity, key).string(), why));
}

std::map<std::string, PipelineCacheCounts> PipelineCache::counts() const
{
    const std::lock_guard lock(mutex_);
    return counts_;
}

std::vector<std::string> PipelineCache::notes() const
{
    const std::lock_guard lock(mutex_);
    return notes_;
}

std::string PipelineCache::summary() const
{
    const std::lock_guard lock(mutex_);
    std::string text = fmt::format("pipeline cache {}:", folder_.string());
    const char* separator = " ";
    for (const auto& [kind, c] : counts_) {
        text +=
            fmt::format("{}{} {} loaded, {} compiled ({:.0f} ms)", separator, kind, c.loaded, c.missed, c.compileMs);
        if (c.ignored > 0)
            text += fmt::format(", {} ignored", c.ignored);
        separator = "; ";
    }
    for (const std::string& n : notes_)
        text += "\n  note: " + n;
    return text;
}

} // namespace penumbra::rhi
