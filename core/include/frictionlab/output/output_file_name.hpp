#pragma once
// Observers name their files in the run's output directory. A name with a folder in it ("../x.csv",
// "/tmp/x.csv") would write outside it, where --overwrite and the run's record cannot follow.
#include <string>

namespace frictionlab {

/// Why `name` cannot be the file name of an output, or "" if it can: what a ParamSpec rule returns.
std::string output_file_name_problem(const std::string& name);

}  // namespace frictionlab
