#include "GltfHugePages.hpp"

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <fstream>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace penumbra::gltf {

std::vector<unsigned char> hugePageBytes(std::size_t size)
{
    std::vector<unsigned char> bytes;
    bytes.reserve(size);
#if defined(__linux__)
    constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;
    const auto first = reinterpret_cast<std::uintptr_t>(bytes.data());
    const std::uintptr_t begin = (first + kHugePage - 1) & ~(kHugePage - 1), end = (first + size) & ~(kHugePage - 1);
    if (end > begin)
        madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#endif
    bytes.resize(size);
    return bytes;
}

bool readWholeFileHugePages(std::vector<unsigned char>* out, std::string* error, const std::string& path, void* user)
{
    std::error_code failed;
    const bool regular = std::filesystem::is_regular_file(path, failed);
    const std::uintmax_t size = regular ? std::filesystem::file_size(path, failed) : 0;
    if (regular && !failed && size > 0) {
        std::ifstream file(path, std::ios::binary);
        std::vector<unsigned char> bytes = hugePageBytes(std::size_t(size));
        if (file.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size))) {
            *out = std::move(bytes);
            return true;
        }
    }
    return tinygltf::ReadWholeFile(out, error, path, user);
}

} // namespace penumbra::gltf
