#include "frictionlab/base/interrupt_signals.hpp"

#include <unistd.h>

#include <csignal>
#include <cstring>

namespace frictionlab {

namespace {

// Only lock-free atomics and write(2)/_exit(2) are used from the handler: async-signal-safe.
std::atomic<int> first_signal{0};
std::atomic<int> writes_in_progress{0};
std::atomic<int> exit_when_written{0};
static_assert(std::atomic<int>::is_always_lock_free);

struct sigaction previous_int, previous_term;

void say(const char* text) {
    const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
    (void)ignored;
}

[[noreturn]] void stop_now(int signal) {
    say("\nfrictionlab: ");
    say(InterruptSignals::name(signal));
    say(" again: stopped at once; every file written so far is whole, run.yaml still says running\n");
    ::_exit(InterruptSignals::exit_status(signal));
}

extern "C" void on_interrupt(int signal) {
    int none = 0;
    if (first_signal.compare_exchange_strong(none, signal)) {
        say("\nfrictionlab: ");
        say(InterruptSignals::name(signal));
        say(" received: finishing the current step and closing the outputs (send it again to stop at once)\n");
        return;
    }
    if (writes_in_progress.load() > 0) {
        exit_when_written.store(signal);
        return;
    }
    stop_now(signal);
}

}  // namespace

InterruptSignals::InterruptSignals() {
    first_signal.store(0);
    exit_when_written.store(0);
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // a write interrupted by the first signal carries on
    sigaction(SIGINT, &action, &previous_int);
    sigaction(SIGTERM, &action, &previous_term);
}

InterruptSignals::~InterruptSignals() {
    sigaction(SIGINT, &previous_int, nullptr);
    sigaction(SIGTERM, &previous_term, nullptr);
}

const std::atomic<int>& InterruptSignals::received() { return first_signal; }

const char* InterruptSignals::name(int signal) {
    return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal";
}

WholeWrite::WholeWrite() noexcept { writes_in_progress.fetch_add(1); }

WholeWrite::~WholeWrite() {
    if (writes_in_progress.fetch_sub(1) == 1)
        if (const int signal = exit_when_written.load(); signal != 0) stop_now(signal);
}

}  // namespace frictionlab
