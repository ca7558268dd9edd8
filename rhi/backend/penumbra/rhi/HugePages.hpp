#pragma once

#include <cstddef>

namespace penumbra::rhi {

// Asks the kernel to back the pages of [data, data + size) with transparent huge pages (madvise(2), MADV_HUGEPAGE),
// for systems that leave them to madvise: a CPU device's textures and staging buffers are ordinary process memory,
// and on a virtual machine each 4 KiB page of a fresh allocation took a page fault as costly as copying the page
// (docs/notes/2026-12-07-loading-time.md). A hint: where it fails (memory the kernel cannot back so, another OS),
// nothing changes.
void adviseHugePages(void* data, std::size_t size);

} // namespace penumbra::rhi
