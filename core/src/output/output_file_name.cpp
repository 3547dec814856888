#include "frictionlab/output/output_file_name.hpp"

namespace frictionlab {

std::string output_file_name_problem(const std::string& name) {
    if (name.empty()) return "must not be empty";
    if (name.find_first_of("/\\") != std::string::npos)
        return "must be a plain file name, in the output directory (no folder, no '..', not absolute)";
    if (name == "." || name == "..") return "must name a file, not '" + name + "'";
    if (name == "run.yaml") return "is the run's own record; choose another name";
    return "";
}

}  // namespace frictionlab
