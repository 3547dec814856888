#pragma once
// The commands that are Python (plot, reproduce): a module of the frictionlab package shipped with
// this frictionlab, run on Debian's python3.
#include <string>
#include <vector>

namespace frictionlab::cli {

/// `python3 -m MODULE ARGUMENTS...` on Debian's Python (FRICTIONLAB_PYTHON overrides), the Python
/// package shipped with this frictionlab first on PYTHONPATH (set here for the child): in the
/// prefix's FRICTIONLAB_PYTHON_INSTALL_SUBDIR once installed, in python/ of the build tree. Throws
/// InputError when the package is in neither.
std::vector<std::string> python_module_command_line(const std::string& module,
                                                    const std::vector<std::string>& arguments);

/// Replaces this process by `args` (a python_module_command_line).
[[noreturn]] void exec(std::vector<std::string> args);

}  // namespace frictionlab::cli
