#pragma once
// Ctrl-C (SIGINT) and SIGTERM during a run: the first asks the run to stop after its current step,
// so it closes every output and records where it stopped; a second stops the process at once, but
// never in the middle of writing a file (a CSV row, run.yaml, a snapshot).
//
// Signal dispositions belong to the process, not to a run, so this is the one piece of
// process-wide state in the core: the command line creates one InterruptSignals around a run and
// hands its flag to RunOptions. A library caller (a Python session) keeps its own handlers and may
// set a flag of its own.
#include <atomic>

namespace frictionlab {

class InterruptSignals {
public:
    /// Installs the handlers for SIGINT and SIGTERM; the destructor puts the previous ones back.
    InterruptSignals();
    ~InterruptSignals();
    InterruptSignals(const InterruptSignals&) = delete;
    InterruptSignals& operator=(const InterruptSignals&) = delete;

    /// The first signal received (0 while none): what RunOptions::stop_signal points to.
    static const std::atomic<int>& received();

    /// Exit status of a command stopped by `signal`, as a shell reports it: 128 + its number
    /// (130 for SIGINT, 143 for SIGTERM).
    static int exit_status(int signal) { return 128 + signal; }
    /// "SIGINT", "SIGTERM", or "a signal".
    static const char* name(int signal);
};

/// While one is alive, a second signal waits for the write in progress to end before it stops the
/// process: a file is written whole or not at all. Costs two atomic operations.
class WholeWrite {
public:
    WholeWrite() noexcept;
    ~WholeWrite();
    WholeWrite(const WholeWrite&) = delete;
    WholeWrite& operator=(const WholeWrite&) = delete;
};

}  // namespace frictionlab
