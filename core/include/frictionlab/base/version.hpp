#pragma once
// Which FrictionLab this is: the release and the commit it was built from.
#include <string>

namespace frictionlab {

/// The framework version, e.g. "0.1.0".
std::string framework_version();
/// The commit the library was built from (`git describe --always --dirty`), "unknown" outside git.
std::string git_revision();

}  // namespace frictionlab
