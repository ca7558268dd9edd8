#pragma once

#include <stdexcept>

namespace penumbra::apps {

// SIGINT or SIGTERM arrived and a long command stopped at its next step; main() exits 128 + the signal.
class Interrupted : public std::runtime_error {
public:
    explicit Interrupted(int signal);
    int signal() const { return signal_; }

private:
    int signal_;
};

// The first SIGINT or SIGTERM only sets a flag, which long commands read between frames, rows and configurations
// (stopIfInterrupted), so that they stop before writing anything more; every file is written whole or not at all
// (rhi::writeFileAtomically). A second signal exits at once, removing the temporary file being written.
void installInterruptHandler();
// Throws Interrupted when a signal has arrived since installInterruptHandler.
void stopIfInterrupted();

} // namespace penumbra::apps
