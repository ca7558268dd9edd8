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

    // The debug groups open where the API reports them to its callback in order (GL's KHR_debug reports each
    // glPushDebugGroup and glPopDebugGroup, GL 4.5 section 20.6), so that messages can name them.
    void openGroup(std::string name);
    void closeGroup();
    // " [labels: outer > inner]" while groups are open, else empty: what a message appends.
    std::string openGroups() const;

private:
    mutable std::mutex mutex_;
    std::vector<std::string> groups_;
    std::vector<std::string> messages_;
    std::size_t reported_ = 0;
};

} // namespace penumbra::rhi
