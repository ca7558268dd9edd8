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

// The results the workers have made and the calling thread has not yet taken, in order.
class MipLevelsQueue {
public:
    MipLevelsQueue(std::size_t count, std::size_t window) : slots_(count), window_(window) {}

    // A worker: generates the next result while it is at most `window` ahead of the last taken, until none is left.
    void work(const std::function<rhi::MipLevels(std::size_t)>& generate)
    {
        for (;;) {
            std::size_t k = 0;
            {
                std::unique_lock lock(mutex_);
                changed_.wait(lock, [&] { return stop_ || next_ >= slots_.size() || next_ < taken_ + window_; });
                if (stop_ || next_ >= slots_.size())
                    return;
                k = next_++;
            }
            MipLevelsSlot made;
            try {
                made.levels = generate(k);
            } catch (...) {
                made.failure = std::current_exception();
            }
            made.done = true;
            {
                const std::lock_guard lock(mutex_);
                slots_[k] = std::move(made);
            }
            changed_.notify_all();
        }
    }

    // Result k, once made (k taken in order).
    MipLevelsSlot take(std::size_t k)
    {
        MipLevelsSlot slot;
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [&] { return slots_[k].done; });
            slot = std::move(slots_[k]);
            taken_ = k + 1;
        }
        changed_.notify_all();
        return slot;
    }

    // The workers start nothing more.
    void stop()
    {
        {
            const std::lock_guard lock(mutex_);
            stop_ = true;
        }
        changed_.notify_all();
    }

private:
    std::vector<MipLevelsSlot> slots_;
    std::size_t window_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::size_t next_ = 0, taken_ = 0;
    bool stop_ = false;
};

} // namespace

void generateMipLevelsInOrder(std::size_t count, const std::function<rhi::MipLevels(std::size_t)>& generate,
                              const std::function<void(std::size_t, const rhi::MipLevels&)>& consume)
{
    const std::size_t threads = std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), count);
    MipLevelsQueue queue(count, 2 * threads);
    std::vector<std::jthread> workers; // joined before the queue goes
    for (std::size_t t = 0; t < threads; ++t)
        workers.emplace_back([&] { queue.work(generate); });
    try {
        for (std::size_t k = 0; k < count; ++k) {
            MipLevelsSlot slot = queue.take(k);
            if (slot.failure)
                std::rethrow_exception(slot.failure);
            consume(k, *slot.levels);
        }
    } catch (...) {
        queue.stop();
        throw;
    }
}

} // namespace penumbra::render
