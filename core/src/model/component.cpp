#include "frictionlab/model/component.hpp"

#include "frictionlab/model/kinds.hpp"

namespace frictionlab {

Component::~Component() = default;
Effect::~Effect() = default;
BulkModel::~BulkModel() = default;
FrictionLaw::~FrictionLaw() = default;
Loader::~Loader() = default;
Observer::~Observer() = default;
Integrator::~Integrator() = default;

std::string_view to_string(Kind kind) {
    switch (kind) {
        case Kind::bulk_model:
            return "bulk_model";
        case Kind::friction_law:
            return "friction_law";
        case Kind::loader:
            return "loader";
        case Kind::observer:
            return "observer";
        case Kind::integrator:
            return "integrator";
    }
    return "?";
}

}  // namespace frictionlab
