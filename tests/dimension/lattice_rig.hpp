#pragma once
// The test lattice assembled in a System, in-process, and the integrators a scene can name, made by
// type as a run makes them (so the hybrid builds its dynamic scheme through the registry).
#include <memory>
#include <string>

#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/simulation/system.hpp"
#include "plugin_test_support.hpp"
#include "test_lattice.hpp"

namespace frictionlab::testing {

/// The schemes every test runs a 3D body through.
inline const std::vector<std::string> every_integrator = {"rk4",        "velocity_verlet", "semi_implicit_euler",
                                                          "imex_euler", "dormand_prince",  "quasi_static_hybrid"};

/// A registry of the integrator types, added by code.
Registry& integrator_registry();

/// Not movable: the system and the effects refer to the lattice's body and the services.
struct LatticeRig {
    explicit LatticeRig(const TestLattice::Params& p);
    LatticeRig(const LatticeRig&) = delete;
    LatticeRig& operator=(const LatticeRig&) = delete;
    /// Adds an effect (a loader built on the body) to the pipeline after the lattice's.
    void add(std::unique_ptr<Effect> effect) { system.add_effect(std::move(effect)); }
    Context context() { return services.context(&lattice.body()); }
    /// The integrator `type` at step dt (an adaptive one at a tight tolerance, its first step dt),
    /// with the values `more` besides.
    std::unique_ptr<Integrator> integrator(const std::string& type, double dt, const ParamValues& more = {});
    /// Kinetic energy plus every effect's stored energy at the accepted state.
    double energy() const;
    /// Steps until t_end, the last step landing on it.
    void run_until(Integrator& integrator, double t_end);

    test_support::Services services;
    TestLattice lattice;
    System system;
};

}  // namespace frictionlab::testing
