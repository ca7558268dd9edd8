#pragma once

#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::rhi {

// For backends: the validation-layer or debug-output messages of one device. Drivers may call
// back from any thread, hence the mutex.
class DebugMessageLog {
public:
    void record(std::string message);
    std::vector<std::string> all() const;
    void clear();
    // Throws Error listing the messages recorded since the previous call, if any (what submit
    // does with DeviceDesc::throwOnDebugMessage); `source` names them ("Vulkan validation").
    void raiseUnreported(std::string_view source);

private:
    mutable std::mutex mutex_;
    std::vector<std::string> messages_;
    std::size_t reported_ = 0;
};

} // namespace penumbra::rhi
