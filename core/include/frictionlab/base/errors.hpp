#pragma once
// The two ways a command fails: bad input (exit code 2) and a run that fails (exit code 1).
#include <stdexcept>
#include <string>

namespace frictionlab {

/// Bad input: a scene, an option, a plugin that cannot be used. Exit code 2.
///
/// Both errors have their destructor defined in the core library, so their vtable and type info live
/// there alone: an error a plugin throws stays valid after the plugin is unloaded while the stack
/// unwinds to the command's handler.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
    ~InputError() override;
};

/// A run that cannot go on (non-finite value, runaway, failed stage check). Exit code 1. Outputs
/// written so far stay valid.
struct RunError : std::runtime_error {
    using std::runtime_error::runtime_error;
    ~RunError() override;
};

/// A run stopped on request (SIGINT, SIGTERM) after a whole step, its outputs closed. The command
/// exits with 128 + the signal's number.
struct Interrupted : RunError {
    Interrupted(const std::string& what, int stopped_by) : RunError(what), signal(stopped_by) {}
    ~Interrupted() override;
    int signal;
};

namespace exit_code {
inline constexpr int ok = 0;
inline constexpr int run_failure = 1;
inline constexpr int bad_input = 2;
}  // namespace exit_code

}  // namespace frictionlab
