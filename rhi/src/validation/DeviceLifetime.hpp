#pragma once

#include <algorithm>
#include <atomic>
#include <mutex>
#include <vector>

namespace penumbra::rhi {

class ValidatingCommandList;

// Shared by a device and its command lists: which lists the device created and whether it still exists, so
// that submit can tell its own lists from others and a list can tell that its device is gone.
struct DeviceLifetime {
    mutable std::mutex mutex; // guards `lists`
    std::atomic<bool> alive = true;
    std::vector<const ValidatingCommandList*> lists;

    bool owns(const void* list) const
    {
        std::lock_guard lock(mutex);
        return std::find(lists.begin(), lists.end(), list) != lists.end();
    }
    bool deviceAlive() const { return alive.load(std::memory_order_acquire); }
};

} // namespace penumbra::rhi
