#include "coulomb.hpp"

#include "frictionlab/model/friction_rules.hpp"

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"

namespace frictionlab {

namespace {

using Params = CoulombStrength::Params;

std::string order_rule(const Params& p) { return moving_not_above_static("mu_d", p.mu_d, p.mu_s); }

}  // namespace

ParamSpec<Params> CoulombStrength::spec() {
    ParamSpec<Params> s(
        "Amontons-Coulomb friction per interface block (Trømborg et al. 2011, doi:10.1103/PhysRevLett.107.074301; "
        "Maegawa et al. 2010): a tangential spring holds a stuck block up to mu_s f_N; a slipping block feels "
        "mu_d f_N against its velocity and re-sticks when it stops or reverses.");
    stick_slip::add_settings(s);
    s.add("mu_d", &Params::mu_d, "Kinetic (dynamic) coefficient: a slipping block feels mu_d f_N against its velocity.")
        .unit("1")
        .at_least(0)
        .also_known_as("mu_k");
    s.rule("mu_d", order_rule);
    return s;
}

CoulombStrength::CoulombStrength(const Params& p) : mu_d_(spec().checked(p).mu_d) {}

std::string CoulombStrength::describe(const stick_slip::Settings& settings, const std::string& stiffness) const {
    return fmt::format("Coulomb friction (mu_s={:.3g}, mu_d={:.3g}, {})", settings.mu_s, mu_d_, stiffness);
}

}  // namespace frictionlab
