#include "frictionlab/base/errors.hpp"

namespace frictionlab {

// The key functions: they anchor the vtables in the core library (errors.hpp says why).
InputError::~InputError() = default;
RunError::~RunError() = default;
Interrupted::~Interrupted() = default;

}  // namespace frictionlab
