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
    const Index positions = 2 * layout_.nodes, aux = layout_.aux;
    const Result parts[] = {part_norm(error.head(positions), y0.head(positions) - reference_,
                                      y1.head(positions) - reference_, tol_.atol_position, tol_.rtol),
                            part_norm(error.segment(positions, positions), y0.segment(positions, positions),
                                      y1.segment(positions, positions), tol_.atol_velocity, tol_.rtol),
                            part_norm(error.tail(aux), y0.tail(aux), y1.tail(aux), tol_.atol_aux, tol_.rtol)};
    Result worst{-1, 0};
    for (int k = 0; k < 3; ++k)
        if (parts[k].value > worst.value) worst = {parts[k].value, parts[k].worst + k * positions};
    return worst;
}

std::string component_name(const StateLayout& layout, Index i) {
    const Index n = layout.nodes;
    if (i >= 4 * n) return fmt::format("auxiliary variable {}", i - 4 * n);
    static constexpr const char* names[] = {"x", "z", "vx", "vz"};
    return fmt::format("{} of block {}", names[i / n], i % n);
}

}  // namespace frictionlab
