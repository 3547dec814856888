#pragma once
// The slider every bulk model describes: its size, mass and Young's modulus (Li2020 Table 1, the
// Maegawa PMMA slider by default), declared once with their docs, units and bounds, so the bulk
// models a scene can swap (spring_lattice_2d, chain_1d) read the same keys the same way.
#include <string>

#include "frictionlab/base/param_spec.hpp"

namespace frictionlab {

/// Base of a bulk model's Params: its flat keys stay flat in the scene.
struct SliderParams {
    double length = 0.1;          // L (x), m
    double height = 0.02;         // H (z), m
    double width = 0.005;         // B (y), m
    double mass = 0.0118;         // M, kg
    double youngs_modulus = 3e9;  // E, Pa
};

/// Declares the SliderParams keys on the spec of a Params derived from it; `springs` says how the
/// model's spring stiffness follows from them (e.g. "K = 3BE/4"), and `masses` how the nodes share
/// the mass, for the docs.
template <class P>
void add_slider_params(ParamSpec<P>& s, const std::string& springs,
                       const std::string& masses = "shared equally by all nodes") {
    const auto key = [&](const char* name, double SliderParams::*member, const std::string& doc, const char* unit) {
        s.template add<double>(name, static_cast<double P::*>(member), doc).unit(unit).greater_than(0);
    };
    key("length", &SliderParams::length, "Slider length L along x, the sliding direction.", "m");
    key("height", &SliderParams::height, "Slider height H along z, normal to the interface.", "m");
    key("width", &SliderParams::width, "Slider width B along y (out of plane).", "m");
    key("mass", &SliderParams::mass, "Total mass M of the slider, " + masses + ".", "kg");
    key("youngs_modulus", &SliderParams::youngs_modulus,
        "Young's modulus E of the slider material; the springs are " + springs + ".", "Pa");
}

}  // namespace frictionlab
