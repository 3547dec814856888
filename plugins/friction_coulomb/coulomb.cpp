#include "coulomb.hpp"

#include "frictionlab/model/friction_rules.hpp"

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"

namespace frictionlab {

namespace {

std::string order_rule(const Coulomb::Params& p) { return moving_not_above_static("mu_k", p.mu_k, p.mu_s); }

const Coulomb::Params& validated(const Coulomb::Params& p) {
    if (const std::string error = order_rule(p); !error.empty()) throw InputError("coulomb: " + error);
    return p;
}

}  // namespace

ParamSpec<Coulomb::Params> Coulomb::spec() {
    ParamSpec<Params> s(
        "Amontons-Coulomb friction per interface block (Trømborg et al. 2011, doi:10.1103/PhysRevLett.107.074301; "
        "Maegawa et al. 2010): a tangential spring holds a stuck block up to mu_s f_N; a slipping block feels "
        "mu_k f_N against its velocity and re-sticks when it stops or reverses.");
    add_settings(s);
    s.add("mu_k", &Params::mu_k, "Kinetic coefficient: a slipping block feels mu_k f_N against its velocity.")
        .unit("1").at_least(0);
    s.rule("mu_k", order_rule);
    return s;
}

Coulomb::Coulomb(const Params& p, const Context& ctx)
    : StickSlipLaw(settings_of(validated(p)), ctx, type), mu_k_(p.mu_k) {
    slipping_ = &quantities_->field("slipping", settings_.node_set, static_cast<Index>(nodes_.size()), "1",
                                    "1 while the block slips, 0 while it is stuck or detached.");
}

std::string Coulomb::describe() const {
    return fmt::format("Coulomb friction (mu_s={:.3g}, mu_k={:.3g}, {})", settings_.mu_s, mu_k_, stiffness_text());
}

void Coulomb::publish(Index i, const Block& b, double /*slip*/) {
    (*slipping_)[i] = b.mode == Mode::slipping ? 1.0 : 0.0;
}

}  // namespace frictionlab
