#include "error_norm.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace frictionlab {

ErrorNorm::ErrorNorm(const Tolerances& tol, const StateLayout& layout, const Eigen::VectorXd& reference_positions)
    : tol_(tol), layout_(layout), reference_(reference_positions) {}

namespace {
/// Largest |e_i| / (atol + rtol max(|a_i|, |b_i|)) over one part of y, with its index in that part.
template <class E, class A, class B>
ErrorNorm::Result part_norm(const E& e, const A& a, const B& b, double atol, double rtol) {
    ErrorNorm::Result r{0, 0};
    if (e.size() == 0) return r;
    r.value = (e.array().abs() / (atol + rtol * a.array().abs().max(b.array().abs()))).maxCoeff(&r.worst);
    return r;
}
}  // namespace

ErrorNorm::Result ErrorNorm::operator()(const Eigen::VectorXd& error, const Eigen::VectorXd& y0,
                                        const Eigen::VectorXd& y1) const {
    if (!error.allFinite()) {
        Index i = 0;
        while (std::isfinite(error(i))) ++i;
        return {std::numeric_limits<double>::infinity(), i};
    }
    const StateLayout& l = layout_;
    const Result parts[] = {
        part_norm(l.positions(error), l.positions(y0) - reference_, l.positions(y1) - reference_, tol_.atol_position,
                  tol_.rtol),
        part_norm(l.velocities(error), l.velocities(y0), l.velocities(y1), tol_.atol_velocity, tol_.rtol),
        part_norm(l.aux_variables(error), l.aux_variables(y0), l.aux_variables(y1), tol_.atol_aux, tol_.rtol)};
    const Index starts[] = {0, l.velocity_start(), l.aux_start()};
    Result worst{-1, 0};
    for (int k = 0; k < 3; ++k)
        if (parts[k].value > worst.value) worst = {parts[k].value, parts[k].worst + starts[k]};
    return worst;
}

std::string component_name(const StateLayout& layout, Index i) {
    if (i >= layout.aux_start()) return fmt::format("auxiliary variable {}", i - layout.aux_start());
    const bool velocity = i >= layout.velocity_start();
    const Index entry = velocity ? i - layout.velocity_start() : i;
    const int axis = static_cast<int>(entry / layout.nodes);
    return fmt::format("{}{} of block {}", velocity ? "v" : "", axis_name(axis, layout.dimension),
                       entry % layout.nodes);
}

}  // namespace frictionlab
