#include "step_size_controller.hpp"

#include <algorithm>
#include <cmath>

namespace frictionlab {

namespace {
constexpr double order = 5;         // error estimate of order 4: err ~ h^5
constexpr double beta = 0.04;       // the P part
constexpr double err_floor = 1e-4;  // the memory of an error far below tolerance (Hairer)
}  // namespace

double StepSizeController::exponent() const { return 1 / order - 0.75 * beta; }

double StepSizeController::factor(double err) const {
    return p_.safety * std::pow(err, -exponent()) * std::pow(previous_err_, beta);  // err = 0: +inf
}

double StepSizeController::accepted(double err, double h, double cap) {
    const double f = factor(err);
    previous_err_ = std::max(err, err_floor);
    const double growth = after_rejection_ ? 1.0 : p_.growth_limit;
    after_rejection_ = false;
    // Asymptotically err ~ h^order: if the cut step's error says the proposal would still pass, keep it.
    if (cap > h && err * std::pow(cap / h, order) <= 1) return cap;
    return h * std::clamp(f, p_.shrink_limit, growth);
}

double StepSizeController::rejected(double err, double h) {
    after_rejection_ = true;
    if (!std::isfinite(err)) return p_.shrink_limit * h;  // a stage overflowed: the estimate is meaningless
    return h * std::max(p_.shrink_limit, p_.safety * std::pow(err, -exponent()));
}

}  // namespace frictionlab
