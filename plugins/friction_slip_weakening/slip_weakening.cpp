#include "slip_weakening.hpp"

#include "frictionlab/model/friction_rules.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"

namespace frictionlab {

namespace {

std::string order_rule(const SlipWeakening::Params& p) { return moving_not_above_static("mu_d", p.mu_d, p.mu_s); }

const SlipWeakening::Params& validated(const SlipWeakening::Params& p) {
    if (const std::string error = order_rule(p); !error.empty()) throw InputError("slip_weakening: " + error);
    return p;
}

}  // namespace

ParamSpec<SlipWeakening::Params> SlipWeakening::spec() {
    ParamSpec<Params> s(
        "Linear slip-weakening friction per interface block (Kammer et al. 2014, doi:10.1016/j.jmps.2013.10.007): "
        "a tangential spring holds a stuck block up to mu_s f_N; a slipping block's strength falls linearly with "
        "its slip since it last stuck, from mu_s f_N to mu_d f_N over D_c.");
    add_settings(s);
    s.add("mu_d", &Params::mu_d, "Residual coefficient, reached after a slip D_c.").unit("1").at_least(0);
    s.add("critical_slip", &Params::critical_slip, "Slip D_c over which the strength weakens from mu_s to mu_d.")
        .unit("m").greater_than(0);
    s.rule("mu_d", order_rule);
    return s;
}

SlipWeakening::SlipWeakening(const Params& p, const Context& ctx)
    : StickSlipLaw(settings_of(validated(p)), ctx, type), mu_d_(p.mu_d), critical_slip_(p.critical_slip) {
    slip_ = &quantities_->field("slip", settings_.node_set, static_cast<Index>(nodes_.size()), "m",
                                "Slip delta of the block since it last stuck (0 while stuck or detached).");
}

std::string SlipWeakening::describe() const {
    return fmt::format("slip-weakening friction (mu_s={:.3g}, mu_d={:.3g}, D_c={:.3g} m, {})", settings_.mu_s, mu_d_,
                       critical_slip_, stiffness_text());
}

double SlipWeakening::kinetic_strength(double normal, double slip) const {
    const double weakened = std::min(slip / critical_slip_, 1.0);
    return (settings_.mu_s - (settings_.mu_s - mu_d_) * weakened) * normal;
}

void SlipWeakening::publish(Index i, const Block& /*b*/, double slip) { (*slip_)[i] = slip; }

}  // namespace frictionlab
