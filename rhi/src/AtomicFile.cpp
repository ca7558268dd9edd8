#include "penumbra/rhi/AtomicFile.hpp"

#include "penumbra/rhi/Error.hpp"

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

namespace penumbra::rhi {
namespace {

// The path a signal handler may unlink: written before the temporary file is created and cleared after it
// is renamed or removed; the flag orders the buffer's writes before the handler's read.
std::array<char, 4096> inProgress{};
std::atomic<bool> inProgressSet{false};

[[noreturn]] void fail(const std::filesystem::path& path, std::string_view why)
{
    throw Error(fmt::format("cannot write {}: {}", path.string(), why));
}

void setInProgress(const std::string& temporary)
{
    inProgressSet.store(false);
    if (temporary.size() >= inProgress.size())
        return;
    std::memcpy(inProgress.data(), temporary.c_str(), temporary.size() + 1);
    inProgressSet.store(true);
}

// write(2) until every byte is out, retrying what a signal interrupted; errno on failure.
int writeAll(int fd, std::string_view bytes)
{
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            return errno;
        bytes.remove_prefix(std::size_t(n));
    }
    return 0;
}

void writeInPlace(const std::filesystem::path& path, std::string_view bytes)
{
    const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0)
        fail(path, std::strerror(errno));
    const int written = writeAll(fd, bytes);
    const int closed = ::close(fd) == 0 ? 0 : errno;
    if (written != 0 || closed != 0)
        fail(path, std::strerror(written != 0 ? written : closed));
}

} // namespace

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes)
{
    struct stat existing {};
    if (::stat(path.c_str(), &existing) == 0) {
        if (S_ISDIR(existing.st_mode))
            fail(path, "it is a folder");
        if (!S_ISREG(existing.st_mode))
            return writeInPlace(path, bytes);
    }
    const std::filesystem::path folder = path.parent_path().empty() ? "." : path.parent_path();
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error)
        fail(path, fmt::format("cannot create the folder {}: {}", folder.string(), error.message()));

    // Named per process, so that two processes writing the same file never share a temporary file.
    const std::string temporary = fmt::format("{}.partial-{}", path.string(), ::getpid());
    setInProgress(temporary);
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) {
        inProgressSet.store(false);
        fail(path, std::strerror(errno));
    }
    int failure = writeAll(fd, bytes);
    if (failure == 0 && ::fsync(fd) != 0)
        failure = errno;
    if (::close(fd) != 0 && failure == 0)
        failure = errno;
    if (failure == 0 && ::rename(temporary.c_str(), path.c_str()) != 0)
        failure = errno;
    if (failure != 0)
        ::unlink(temporary.c_str());
    inProgressSet.store(false);
    if (failure != 0)
        fail(path, std::strerror(failure));
}

const char* temporaryFileInProgress() noexcept { return inProgressSet.load() ? inProgress.data() : ""; }

} // namespace penumbra::rhi
