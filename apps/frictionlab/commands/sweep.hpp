#pragma once
// What `check` takes from the sweep command: `check SWEEP.yaml` is `sweep --check SWEEP.yaml`.
#include <filesystem>
#include <string>

#include "command.hpp"

namespace frictionlab::cli {

/// Validates the sweep and the scene of every run, each run's stable step too; `output`: as -o.
int check_sweep(const std::filesystem::path& file, const std::string& output, const Invocation& in);

}  // namespace frictionlab::cli
