#include "velocity_verlet.hpp"

#include <algorithm>

#include "frictionlab/base/parallel_chunks.hpp"
#include "frictionlab/model/partitioned_step.hpp"
#include "frictionlab/simulation/system.hpp"

namespace frictionlab {

ParamSpec<VelocityVerlet::Params> VelocityVerlet::spec() {
    return fixed_step_spec(
        "Velocity Verlet (kick-drift-kick), fixed step, 2nd order; symplectic for position-dependent forces, "
        "velocity-dependent forces at the Euler-predicted end velocity; stable for omega*dt < 2.");
}

VelocityVerlet::VelocityVerlet(const Params& p, const Context&) : FixedStepIntegrator(p) {}

namespace {
/// Kick-drift-kick from y into out; velocity-dependent forces at the end are taken at the
/// Euler-predicted velocity v_n + h a_n. `rate(t_offset, state, dy)` is dy/dt at t + t_offset.
template <class Rate>
void verlet_step(Rate&& rate, double h, Index p, const Eigen::VectorXd& y, Eigen::VectorXd& start, Eigen::VectorXd& end,
                 Eigen::VectorXd& out) {
    const Index rest = y.size() - p;  // velocities and aux, whose rates are updated together
    rate(0.0, y, start);
    out.resize(y.size());
    for_each_chunk(y.size(), [&](Index from, Index to) { out.segment(from, to - from) = y.segment(from, to - from); });
    kick(out, start, 0.5 * h, p);  // v_half (aux: half an Euler step)
    drift(out, h, p);              // drift with v_half
    kick(out, start, 0.5 * h, p);  // predictor: v_n + h a_n, psi_n + h g_n
    rate(h, out, end);
    for_each_chunk(rest, [&](Index from, Index to) {  // kick
        const Index i = p + from, m = to - from;
        out.segment(i, m) = y.segment(i, m) + (0.5 * h) * (start.segment(i, m) + end.segment(i, m));
    });
}
}  // namespace

double VelocityVerlet::step(System& system, double max_dt) {
    const double h = std::min(dt_, max_dt);
    const double t = system.time();
    const Eigen::VectorXd& y = system.y();
    if (stage_.size() != y.size())
        for (auto* v : {&start_rate_, &end_rate_, &stage_}) v->resize(y.size());

    system.begin_step();
    // Each of the two evaluations carries weight h/2 in work accounting (trapezoidal rule).
    const auto rate = [&](double offset, const Eigen::VectorXd& s, Eigen::VectorXd& dy) {
        derivative(system, t + offset, s, dy, Evaluation::weighted(h / 2));
    };
    verlet_step(rate, h, system.layout().dof(), y, start_rate_, end_rate_, stage_);
    system.accept(t + h, stage_);
    return h;
}

bool VelocityVerlet::linearised_step(const JacobianProduct& jacobian, double h, Index positions,
                                     const Eigen::VectorXd& u, Eigen::VectorXd& out) const {
    Eigen::VectorXd start, end;
    verlet_step([&](double, const Eigen::VectorXd& s, Eigen::VectorXd& dy) { jacobian(s, dy); }, h, positions, u, start,
                end, out);
    return true;
}

}  // namespace frictionlab
