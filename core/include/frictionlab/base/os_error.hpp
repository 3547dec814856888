#pragma once
// The system's reason for a failed call, as a user can search for it: "No space left on device
// (ENOSPC)".
#include <string>

namespace frictionlab {

/// strerror(error) followed by the errno's symbolic name.
std::string os_error(int error);

}  // namespace frictionlab
