#pragma once

#include "penumbra/opengl/GlFunctions.hpp"

#include <mutex>
#include <string>
#include <vector>

namespace penumbra::opengl {

// Messages from KHR_debug output; Mesa may call back from any thread, hence the mutex.
class GlDebugLog {
public:
    void record(std::string message);
    std::vector<std::string> messages() const;
    // Messages recorded since the last call, for submit's throwOnDebugMessage.
    std::vector<std::string> takeUnreported();
    void clear();

private:
    mutable std::mutex mutex_;
    std::vector<std::string> messages_;
    std::size_t reported_ = 0;
};

// Turns on synchronous debug output on the current context, recording into `log`.
void enableDebugOutput(const GlFunctions& gl, GlDebugLog& log);

} // namespace penumbra::opengl
