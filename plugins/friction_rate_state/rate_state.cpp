#include "rate_state.hpp"

#include <cmath>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/rupture_scales.hpp"

namespace frictionlab {

ParamSpec<RateState::Params> RateState::spec() {
    ParamSpec<Params> s(
        "Rate-and-state friction (Dieterich 1979, doi:10.1029/JB084iB05p02161; Ruina 1983, "
        "doi:10.1029/JB088iB12p10359), regularised: mu = a asinh[(v/2v0) exp(psi/a)] with the state psi "
        "integrated with the bulk (aging or slip law); force -mu f_N on each interface block.");
    s.add("a", &Params::a,
          "Direct-effect coefficient a: an instantaneous velocity step v1 -> v2 raises mu by a ln(v2/v1).")
        .unit("1")
        .greater_than(0);
    s.add("b", &Params::b, "Evolution-effect coefficient b: the steady state changes by (a - b) ln(v2/v1).")
        .unit("1")
        .greater_than(0);
    s.add("d_c", &Params::d_c, "Characteristic slip distance D_c over which psi evolves to its new steady state.")
        .unit("m")
        .greater_than(0)
        .also_known_as("critical_slip");
    s.add("f0", &Params::f0, "Reference friction coefficient f0: the steady-state mu at v = v0.")
        .unit("1")
        .greater_than(0);
    s.add("v0", &Params::v0, "Reference slip velocity v0.").unit("m/s").greater_than(0);
    s.add("initial_velocity", &Params::initial_velocity,
          "psi starts at its steady state psi_ss = f0 - b ln(v/v0) for this velocity (both laws).")
        .unit("m/s")
        .greater_than(0);
    s.choice("law", &Params::law, {{"aging", Law::aging}, {"slip", Law::slip}},
             "State evolution: aging, dpsi/dt = (b v0/D_c)[exp((f0 - psi)/b) - |v|/v0]; or slip, "
             "dpsi/dt = -(|v|/D_c)(psi - psi_ss(v)).");
    s.add("node_set", &Params::node_set, "The bulk's node set in contact with the base.");
    s.dimensions({2}, "x-velocity and x-force of each block, its velocity dependence implicit along x alone");
    return s;
}

RateState::RateState(const Params& params, const Context& ctx) : p_(spec().checked(params)), law_(params.law) {
    const std::string name = ctx.name.empty() ? std::string(type) : ctx.name;
    if (!ctx.body || !ctx.quantities || !ctx.aux)
        throw InputError(name + ": needs the bulk model's body, the run's quantities and an aux allocator");
    nodes_ = ctx.body->nodes(params.node_set);
    const Index n = static_cast<Index>(nodes_.size());
    offset_ = ctx.aux->allocate(n);
    Quantities& q = *ctx.quantities;
    const std::string& set = params.node_set;
    normal_force_ = &q.needed_field("normal_force", set, n, name);
    friction_force_ = &q.field("friction_force", set, n, "N", "x-force on the block from the friction law.");
    state_ = &q.field("state_variable", set, n, "1", "Rate-and-state variable psi of the block.");
    // No elastic contact: the state's slip scale D_c stands for it; f0 is the steady-state level at v0.
    rupture_scales::publish_characteristic_slip(q, p_.d_c);
    rupture_scales::publish_kinetic_coefficient(q, p_.f0);
}

double RateState::coefficient(double v, double psi) const {
    return p_.a * std::asinh(v / (2 * p_.v0) * std::exp(psi / p_.a));
}

double RateState::steady_state(double v) const { return p_.f0 - p_.b * std::log(std::abs(v) / p_.v0); }

double RateState::state_rate(double v, double psi) const {
    const double speed = std::abs(v);
    if (law_ == Law::aging) return p_.b * p_.v0 / p_.d_c * (std::exp((p_.f0 - psi) / p_.b) - speed / p_.v0);
    // |v| ln|v| -> 0: a block at rest neither heals nor weakens under the slip law.
    if (speed == 0) return 0;
    return -speed / p_.d_c * (psi - steady_state(speed));
}

std::string RateState::describe() const {
    return fmt::format("rate-and-state friction ({} law, a={:.3g}, b={:.3g}, D_c={:.3g} m)",
                       law_ == Law::aging ? "aging" : "slip", p_.a, p_.b, p_.d_c);
}

void RateState::add_forces(const StageView& s, ForceView& f) {
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const auto i = static_cast<Index>(k);
        const Index node = nodes_[k];
        const double v = s.vx[node], psi = s.aux[offset_ + i];
        const double force = -coefficient(v, psi) * (*normal_force_)[i];
        f.fx[node] += force;
        f.aux_rate[offset_ + i] += state_rate(v, psi);
        (*friction_force_)[i] = force;
        (*state_)[i] = psi;
    }
}

double RateState::coefficient_slope(double v, double psi) const {
    // w underflows to 0 rather than overflowing where exp(psi/a) would: the slope is then a/|v|.
    return p_.a / std::hypot(v, 2 * p_.v0 * std::exp(-psi / p_.a));
}

void RateState::add_velocity_jacobian(const StageView& s, LocalVelocityJacobian& j) const {
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const auto i = static_cast<Index>(k);
        const Index node = nodes_[k];
        j.slope[node] -= coefficient_slope(s.vx[node], s.aux[offset_ + i]) * (*normal_force_)[i];
    }
}

void RateState::initialise_aux(Eigen::Ref<Eigen::ArrayXd> aux) const {
    aux.segment(offset_, blocks()).setConstant(steady_state(p_.initial_velocity));
}

}  // namespace frictionlab
