#include "lattice_rig.hpp"

#include "dormand_prince.hpp"
#include "imex_euler.hpp"
#include "quasi_static_hybrid.hpp"
#include "rk4.hpp"
#include "semi_implicit_euler.hpp"
#include "velocity_verlet.hpp"

namespace frictionlab::testing {

Registry& integrator_registry() {
    static Registry registry;
    static const bool filled = [] {
        registry.add<Rk4>();
        registry.add<VelocityVerlet>();
        registry.add<SemiImplicitEuler>();
        registry.add<ImexEuler>();
        registry.add<DormandPrince>();
        registry.add<QuasiStaticHybrid>();
        return true;
    }();
    (void)filled;
    return registry;
}

LatticeRig::LatticeRig(const TestLattice::Params& p) : lattice(p, services.context()), system(lattice.body(), 0) {
    for (auto& e : lattice.effects(context())) system.add_effect(std::move(e));
}

std::unique_ptr<Integrator> LatticeRig::integrator(const std::string& type, double dt, const ParamValues& more) {
    Context ctx = context();
    ctx.registry = &integrator_registry();
    ParamValues values{{"dt", dt}};
    if (type == "dormand_prince")
        values = {{"rtol", 1e-10}, {"atol_position", 1e-16}, {"atol_velocity", 1e-12}, {"initial_step", dt}};
    values.insert(more.begin(), more.end());
    return integrator_registry().create<Integrator>(type, values, ctx);
}

double LatticeRig::energy() const {
    const StageView s = system.state();
    double e = 0.5 * (lattice.body().mass * s.velocity.square().rowwise().sum()).sum();
    system.for_each_effect([&](const Effect& effect) { e += effect.potential_energy(s); });
    return e;
}

void LatticeRig::run_until(Integrator& integrator, double t_end) {
    while (t_end - system.time() > 1e-9 * integrator.nominal_dt()) integrator.step(system, t_end - system.time());
}

}  // namespace frictionlab::testing
