#pragma once

#include <filesystem>
#include <string_view>

namespace penumbra::rhi {

// Every file Penumbra's libraries and tools write (pictures, EXR, JSON, HTML, settings) goes through here.
// The bytes go to a temporary file in the same folder ("<name>.partial-<pid>"), which is flushed to the disk
// and renamed over the path, so a reader sees the old file or the whole new one, never half of it (rename(2)
// is atomic within a file system, POSIX.1-2017 "rename"). Parent folders are created. A path that exists and
// is not a regular file (/dev/stdout, /dev/full, a FIFO) is written in place, since renaming over it would
// replace the device. Any failure throws rhi::Error "cannot write <path>: <reason>" and leaves no temporary
// file behind.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

// The temporary file being written at this moment ("" when none), for a SIGINT handler that exits at once:
// reading it is async-signal-safe (a fixed buffer, no allocation), so the handler can unlink(2) it.
const char* temporaryFileInProgress() noexcept;

} // namespace penumbra::rhi
