#include "MipLevelsInOrder.hpp"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace penumbra::render {
namespace {

struct MipLevelsSlot {
    std::optional<rhi::MipLevels> levels;
    std::exception_ptr failure;
    bool done = false;
};

} // namespace

void generateMipLevelsInOrder(std::size_t count, const std::function<rhi::MipLevels(std::size_t)>& generate,
                              const std::function<void(std::size_t, const rhi::MipLevels&)>& consume)
{
    const std::size_t threads = std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), count);
    const std::size_t window = 2 * threads;
    std::vector<MipLevelsSlot> slots(count);
    std::mutex mutex;
    std::condition_variable changed;
    std::size_t next = 0, consumed = 0;
    bool stop = false;
    const auto work = [&] {
        for (;;) {
            std::size_t k = 0;
            {
                std::unique_lock lock(mutex);
                changed.wait(lock, [&] { return stop || next >= count || next < consumed + window; });
                if (stop || next >= count)
                    return;
                k = next++;
            }
            MipLevelsSlot made;
            try {
                made.levels = generate(k);
            } catch (...) {
                made.failure = std::current_exception();
            }
            made.done = true;
            {
                const std::lock_guard lock(mutex);
                slots[k] = std::move(made);
            }
            changed.notify_all();
        }
    };
    const auto stopWorkers = [&] {
        {
            const std::lock_guard lock(mutex);
            stop = true;
        }
        changed.notify_all();
    };
    std::vector<std::jthread> workers; // joined before the state above goes
    for (std::size_t t = 0; t < threads; ++t)
        workers.emplace_back(work);
    try {
        for (std::size_t k = 0; k < count; ++k) {
            MipLevelsSlot slot;
            {
                std::unique_lock lock(mutex);
                changed.wait(lock, [&] { return slots[k].done; });
                slot = std::move(slots[k]);
                consumed = k + 1;
            }
            changed.notify_all();
            if (slot.failure)
                std::rethrow_exception(slot.failure);
            consume(k, *slot.levels);
        }
    } catch (...) {
        stopWorkers();
        throw;
    }
}

} // namespace penumbra::render
