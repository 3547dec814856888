#include "frictionlab/base/os_error.hpp"

#include <cstring>

namespace frictionlab {

std::string os_error(int error) {
    std::string text = std::strerror(error);
    if (const char* name = strerrorname_np(error)) text += std::string(" (") + name + ")";
    return text;
}

}  // namespace frictionlab
