#pragma once
// What the study command takes from the plot command: frictionlab.plot, run as a child.
#include <string>
#include <vector>

namespace frictionlab::cli {

/// Runs frictionlab.plot with `arguments` and waits for it: true if it succeeded.
bool plot_and_wait(const std::vector<std::string>& arguments);

}  // namespace frictionlab::cli
