#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::rhi {

// Compiled shaders and pipelines kept on disk, so that a second process skips compilation. A device given one
// (DeviceDesc::pipelineCache) keeps there:
//   - "spirv": glslang's SPIR-V of every shader, keyed by its source, includes, preamble and glslang's version;
//   - "vulkan": the device's VkPipelineCache data, keyed by vendor, device, driver version and pipelineCacheUUID,
//     the header checked as the Vulkan 1.3 specification's section 10.7 "Pipeline Cache" lays it out;
//   - "opengl": one program binary per linked program (glGetProgramBinary), keyed by the driver's vendor, renderer
//     and version and by the program's GLSL, where the driver reports formats (Capabilities::pipelineBinaries).
// Each entry is one file "<kind>-<hash>.bin" holding a header (magic, format version, identity, key, payload size
// and checksum) and the payload. A file that is corrupt, truncated or written for another driver, device or key
// is ignored with a note (notes()) and compiled anew, never trusted. Writes are atomic (writeFileAtomically), so
// processes sharing a folder see an old entry or a whole new one. Nothing here throws: a cache only saves time.
// Thread-safe: devices on several threads may share one.

// The tools' cache folder: $XDG_CACHE_HOME/penumbra, else $HOME/.cache/penumbra (XDG Base Directory
// Specification 0.8, "$XDG_CACHE_HOME"); empty where neither variable is set.
std::filesystem::path defaultPipelineCacheFolder();

// What happened to one kind of entry since the cache was opened.
struct PipelineCacheCounts {
    std::uint32_t loaded = 0; // entries found and valid: compilation skipped
    std::uint32_t missed = 0; // no entry, or one ignored: compiled
    std::uint32_t ignored = 0; // of the missed, entries found but refused (each with a note)
    std::uint32_t stored = 0;
    double compileMs = 0.0; // wall time of the compilations the misses needed
};

class PipelineCache {
public:
    // Files go into `folder`, created at the first store.
    explicit PipelineCache(std::filesystem::path folder);
    PipelineCache(const PipelineCache&) = delete;
    PipelineCache& operator=(const PipelineCache&) = delete;

    const std::filesystem::path& folder() const { return folder_; }

    // The payload stored for (kind, identity, key); nullopt when there is none or the file is refused (a note).
    // `identity` names what produced the payload (compiler or driver and device); `key` what it was made from.
    std::optional<std::string> load(std::string_view kind, std::string_view identity, std::string_view key);
    // Writes the entry atomically; a failure is a note. `compileMs`: what making the payload cost.
    void store(std::string_view kind, std::string_view identity, std::string_view key, std::string_view payload,
               double compileMs);
    // A payload that load() returned but its user refused after all (a driver that rejects a program binary):
    // counted as ignored and missed instead of loaded, with the note.
    void refuse(std::string_view kind, std::string_view identity, std::string_view key, std::string_view why);

    // The file of an entry (tests corrupt it).
    std::filesystem::path entryPath(std::string_view kind, std::string_view identity, std::string_view key) const;
    // Per kind ("spirv", "vulkan", "opengl").
    std::map<std::string, PipelineCacheCounts> counts() const;
    // Every entry ignored and why, every write that failed.
    std::vector<std::string> notes() const;
    // One line for the tools: "<folder>: spirv 12 loaded, 0 compiled; vulkan 1 loaded, ..." and the notes.
    std::string summary() const;

private:
    void note(std::string text);

    std::filesystem::path folder_;
    mutable std::mutex mutex_;
    std::map<std::string, PipelineCacheCounts> counts_;
    std::vector<std::string> notes_;
};

} // namespace penumbra::rhi
