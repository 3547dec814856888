#pragma once
// What `check` takes from the study command: `check STUDY.yaml` is `study --check STUDY.yaml`.
#include <filesystem>
#include <string>

#include "command.hpp"

namespace frictionlab::cli {

/// Validates the study and the scene of every run, warning of runs above their stable step;
/// `output`: as -o.
int check_study(const std::filesystem::path& file, const std::string& output, const Invocation& in);

}  // namespace frictionlab::cli
