#include "penumbra/rhi/HugePages.hpp"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace penumbra::rhi {

void adviseHugePages(void* data, std::size_t size)
{
#if defined(__linux__)
    // madvise takes a page-aligned start; the kernel uses huge pages where whole 2 MiB extents lie in the range.
    const auto page = std::uintptr_t(sysconf(_SC_PAGESIZE));
    const auto first = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t begin = (first + page - 1) & ~(page - 1), end = first + size;
    if (end > begin)
        madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
    (void)data;
    (void)size;
#endif
}

} // namespace penumbra::rhi
