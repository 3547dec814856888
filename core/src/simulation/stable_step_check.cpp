#include "frictionlab/simulation/stable_step_check.hpp"

#include "frictionlab/base/errors.hpp"
#include "frictionlab/simulation/simulation.hpp"

namespace frictionlab {

void check_stable_steps(const Scene& scene, const Registry& registry, spdlog::logger& log, Diagnostics& diagnostics) {
    const auto dt = scene.integrator.value_where.find("dt");
    const SourceLocation where = dt != scene.integrator.value_where.end() ? dt->second : scene.integrator.where;
    Simulation simulation(scene, registry, log);  // a component's refusal propagates, located
    simulation.refuse_unstable_steps(true);
    try {
        // The first stage only: later stages start from states only a run reaches (a settled
        // interface, junctions formed), and the run estimates again before each of them.
        if (!scene.stages.empty()) simulation.begin_stage(0);
    } catch (const InputError& e) {
        diagnostics.error(where, "integrator.dt", e.what());
    }
}

}  // namespace frictionlab
