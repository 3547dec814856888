#include "frictionlab/output/output_file_name.hpp"

#include "frictionlab/output/output_directory.hpp"

namespace frictionlab {

bool is_run_file(std::string_view name) {
    return name == "run.yaml" || name == output_marker_file || name.starts_with("checkpoint.") ||
           name.ends_with(".tmp");
}

std::string output_file_name_problem(const std::string& name) {
    if (name.empty()) return "must not be empty";
    if (name.find_first_of("/\\") != std::string::npos)
        return "must be a plain file name, in the output directory (no folder, no '..', not absolute)";
    if (name == "." || name == "..") return "must name a file, not '" + name + "'";
    if (is_run_file(name))
        return "'" + name +
               "' is a name of the run's own files (run.yaml, checkpoint.*, .frictionlab-output, *.tmp); choose "
               "another name";
    return "";
}

}  // namespace frictionlab
