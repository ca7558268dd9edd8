#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

namespace penumbra::truth {

// Runs traceRow(row) for every row in [0, rows) on every hardware thread. Rows are independent, so the
// result does not depend on the thread count. `progress(done, rows)` is called on the calling thread only,
// after each row it traced itself, with the rows finished so far.
inline void forEachRow(std::uint32_t rows, const std::function<void(std::uint32_t)>& traceRow,
                       const std::function<void(std::uint32_t, std::uint32_t)>& progress)
{
    std::atomic<std::uint32_t> next{0};
    std::atomic<std::uint32_t> done{0};
    const auto work = [&](bool reports) {
        for (std::uint32_t row = next++; row < rows; row = next++) {
            traceRow(row);
            const std::uint32_t finished = ++done;
            if (reports && progress)
                progress(finished, rows);
        }
    };
    const unsigned helpers = std::max(1u, std::thread::hardware_concurrency()) - 1;
    std::vector<std::jthread> threads;
    for (unsigned i = 0; i < helpers && i + 1 < rows; ++i)
        threads.emplace_back(work, false);
    try {
        work(true);
    } catch (...) {
        // A progress callback that throws (the tool's SIGINT check) stops the helpers after their current row.
        next = rows;
        threads.clear();
        throw;
    }
    threads.clear();
    if (progress)
        progress(rows, rows);
}

} // namespace penumbra::truth
