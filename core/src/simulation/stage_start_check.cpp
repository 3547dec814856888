#include "frictionlab/simulation/stage_start_check.hpp"

#include "frictionlab/base/errors.hpp"
#include "frictionlab/simulation/simulation.hpp"

namespace frictionlab {

void check_stage_starts(const Scene& scene, const Registry& registry, spdlog::logger& log, Diagnostics& diagnostics,
                        std::vector<std::string>* stable_steps) {
    const auto dt = scene.integrator.value_where.find("dt");
    const SourceLocation where = dt != scene.integrator.value_where.end() ? dt->second : scene.integrator.where;
    // Every stage's pipeline, each from the initial state: a stage switches on effects of its own (a
    // stiff driving spring only while loading). Friction events stay off after the first stage: a law
    // entering them judges the interface the earlier stages leave (settled, its junctions formed),
    // which only running them gives; the linearised forces are the same.
    Scene at_start = scene;
    for (std::size_t i = 1; i < at_start.stages.size(); ++i) at_start.stages[i].friction_events = false;
    Simulation simulation(at_start, registry, log);  // a component's refusal propagates, located
    simulation.refuse_unstable_steps(true);
    for (std::size_t i = 0; i < at_start.stages.size(); ++i) {
        bool refused = false;
        try {
            simulation.begin_stage(i);
            if (stable_steps)
                stable_steps->push_back("stage '" + at_start.stages[i].name + "': " + simulation.stable_step_note());
        } catch (const InputError& e) {
            diagnostics.error(where, "integrator.dt", e.what());
            refused = true;  // the later stages' estimates would most likely say the same
        }
        const std::string cannot_rest = simulation.cannot_end_at_rest(i);
        if (!cannot_rest.empty())
            diagnostics.error(at_start.stages[i].where, "stages[" + std::to_string(i) + "]", cannot_rest);
        if (refused) break;
    }
}

}  // namespace frictionlab
