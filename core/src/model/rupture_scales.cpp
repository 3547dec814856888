#include "frictionlab/model/rupture_scales.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace frictionlab::rupture_scales {

void publish_drive_velocity(Quantities& q, double velocity) {
    q.scalar(std::string(drive_velocity_name), "m/s",
             "Speed |V| of the drive's far end: the loading's own rate, against which the rupture detector judges "
             "a block quiet.") = std::abs(velocity);
}

double& publish_characteristic_slip(Quantities& q, double slip) {
    double& value = q.scalar(std::string(characteristic_slip_name), "m",
                             "Slip a contact takes, from unloaded, before it breaks: more is slip, not "
                             "elastic stretch; the rupture detector's scale of slip (NaN until known).");
    value = slip;
    return value;
}

void publish_kinetic_coefficient(Quantities& q, double coefficient) {
    q.scalar(std::string(kinetic_coefficient_name), "1",
             "The friction law's kinetic level of F/f_N: a global slip starting far below it is suspect.") =
        coefficient;
}

Eigen::ArrayXd& publish_slipping(Quantities& q, const std::string& node_set, Eigen::Index blocks) {
    return q.field(std::string(slipping_name), node_set, blocks, "1",
                   "1 while the block slips, 0 while it is stuck or detached.");
}

double find(const Quantities& q, std::string_view name) {
    const Quantities::Scalar* s = q.find_scalar(name);
    return s ? s->value : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace frictionlab::rupture_scales
