#pragma once
// The settings the junction laws declare alike (friction_three_state_junctions,
// friction_two_state_junctions): one junction's static and moving coefficients with their order
// rule, the node set and the dimensions the laws work in. Declared once, so both laws say them in
// the same words and check them by the same rule (as the stick-slip laws' stick_slip::add_settings).
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/model/friction_rules.hpp"

namespace frictionlab::junction_settings {

/// mu_s and mu_d of one junction; `load` is its normal load in the law's symbols ("p",
/// "f_N / N_s"), `moving` the name of its moving state ("sliding", "slipping").
template <class P>
void add_coefficients(ParamSpec<P>& s, const std::string& load, const std::string& moving) {
    s.add("mu_s", &P::mu_s,
          fmt::format("Static coefficient of one junction: a pinned junction breaks when |f| > mu_s {}.", load))
        .unit("1")
        .greater_than(0);
    s.add("mu_d", &P::mu_d,
          fmt::format("Moving coefficient of one junction: a {} junction carries mu_d {}.", moving, load))
        .unit("1")
        .at_least(0)
        .also_known_as("mu_k");
    s.rule("mu_d", [](const P& p) { return moving_not_above_static("mu_d", p.mu_d, p.mu_s); });
}

/// The node set in contact with the base, and the dimensions a junction law works in (why not in
/// others, when it does not work in every one).
template <class P>
void add_interface(ParamSpec<P>& s, std::vector<int> dimensions, const std::string& limit = {}) {
    s.add("node_set", &P::node_set, "The bulk's node set in contact with the base.");
    s.dimensions(std::move(dimensions), limit);
}

}  // namespace frictionlab::junction_settings
