#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace penumbra::gltf {

// `size` bytes (zeroed) whose pages the kernel may back with transparent huge pages (madvise(2), MADV_HUGEPAGE, for
// systems that leave them to madvise): a fresh 16 MiB picture otherwise takes 4096 page faults, and page faults were
// a third of loading a dozen 2048 x 2048 textures on a virtual machine. A hint: where it fails, nothing changes.
std::vector<unsigned char> hugePageBytes(std::size_t size);

// tinygltf's ReadWholeFile callback (tinygltf::FsCallbacks) for external buffers and images, reading a regular file
// into hugePageBytes: a 131 MB .bin took 32 000 page faults (docs/notes/2026-12-07-loading-time.md). Anything else,
// and any failure, goes to tinygltf's own reader, whose messages the loader's errors quote.
bool readWholeFileHugePages(std::vector<unsigned char>* out, std::string* error, const std::string& path, void* user);

} // namespace penumbra::gltf
