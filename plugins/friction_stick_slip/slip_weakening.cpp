#include "slip_weakening.hpp"

#include "frictionlab/model/friction_rules.hpp"

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"

namespace frictionlab {

namespace {

using Params = SlipWeakeningStrength::Params;

std::string order_rule(const Params& p) { return moving_not_above_static("mu_d", p.mu_d, p.mu_s); }

}  // namespace

ParamSpec<Params> SlipWeakeningStrength::spec() {
    ParamSpec<Params> s(
        "Linear slip-weakening friction per interface block (Kammer et al. 2014, doi:10.1016/j.jmps.2013.10.007): "
        "a tangential spring holds a stuck block up to mu_s f_N; a slipping block's strength falls linearly with "
        "its slip since it last stuck, from mu_s f_N to mu_d f_N over D_c.");
    stick_slip::add_settings(s);
    s.add("mu_d", &Params::mu_d, "Residual coefficient, reached after a slip D_c.")
        .unit("1")
        .at_least(0)
        .also_known_as("mu_k");
    s.add("critical_slip", &Params::critical_slip, "Slip D_c over which the strength weakens from mu_s to mu_d.")
        .unit("m")
        .greater_than(0)
        .also_known_as("d_c");
    s.rule("mu_d", order_rule);
    return s;
}

SlipWeakeningStrength::SlipWeakeningStrength(const Params& p)
    : mu_s_(spec().checked(p).mu_s), mu_d_(p.mu_d), critical_slip_(p.critical_slip) {}

void SlipWeakeningStrength::declare(Quantities& q, const std::string& node_set, Index blocks) {
    slip_ = &q.field("slip", node_set, blocks, "m",
                     "Slip delta of the block since it last stuck (0 while stuck or detached).");
}

std::string SlipWeakeningStrength::describe(const stick_slip::Settings& settings, const std::string& stiffness) const {
    return fmt::format("slip-weakening friction (mu_s={:.3g}, mu_d={:.3g}, D_c={:.3g} m, {})", settings.mu_s, mu_d_,
                       critical_slip_, stiffness);
}

}  // namespace frictionlab
