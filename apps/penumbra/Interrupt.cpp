#include "Interrupt.hpp"

#include "penumbra/rhi/AtomicFile.hpp"

#include <csignal>
#include <cstring>
#include <fmt/format.h>
#include <unistd.h>

namespace penumbra::apps {
namespace {

volatile std::sig_atomic_t arrived = 0;

// Only async-signal-safe calls here (POSIX.1-2017 2.4.3 "Signal Actions"): unlink(2) and _exit(2).
extern "C" void onInterrupt(int signal)
{
    if (arrived != 0) {
        if (const char* temporary = rhi::temporaryFileInProgress(); temporary[0] != '\0')
            ::unlink(temporary);
        ::_exit(128 + signal);
    }
    arrived = signal;
}

} // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(fmt::format("interrupted by {}: stopped before writing anything more",
                                     signal == SIGINT ? "SIGINT" : ::strsignal(signal))),
      signal_(signal)
{
}

void installInterruptHandler()
{
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    for (int signal : {SIGINT, SIGTERM})
        if (::sigaction(signal, &action, nullptr) != 0)
            throw std::runtime_error(fmt::format("cannot install the signal handler: {}", std::strerror(errno)));
}

void stopIfInterrupted()
{
    if (arrived != 0)
        throw Interrupted(arrived);
}

} // namespace penumbra::apps
