#pragma once
// A scene assembled into a runnable system: the components built through the registry, the force
// pipeline in evaluation order (bulk effects, loaders, friction law), the integrator. It knows
// nothing of outputs; run_scene() drives it with observers, and tests and benchmarks drive it
// directly.
#include <memory>
#include <new>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <spdlog/logger.h>

#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/scene_errors.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/model/quantities.hpp"
#include "frictionlab/simulation/run.hpp"
#include "frictionlab/scene/scene.hpp"
#include "frictionlab/simulation/system.hpp"

namespace frictionlab {

class Registry;

/// Runs `make`, which builds the scene component `c`, and reports a refusal it throws (InputError)
/// at the component's place in the scene, as SceneErrors: "scene.yaml:16:5: error: loaders[2]:
/// ...". Components can only judge some set-ups once built (a driving point between node rows, say).
/// Memory running out while it is built names the component too (a RunError): its sizes are the
/// ones to reduce.
template <class Make>
auto located_in_scene(const ComponentSpec& c, Make&& make) -> decltype(make()) {
    try {
        return make();
    } catch (const SceneErrors&) {
        throw;  // located already (a component that builds another through the registry)
    } catch (const InputError& e) {
        throw SceneErrors(Diagnostic{c.where, c.path, e.what()});
    } catch (const std::bad_alloc&) {
        throw RunError(fmt::format("out of memory while building {} ({}, {}:{}:{}); make the sizes it is given smaller",
                                   c.path, c.type, c.where.file, c.where.line, c.where.column));
    }
}

class Simulation {
public:
    /// Builds every component of the scene, observers last. Every component that refuses its
    /// set-up, and every field a component reads that no effect publishes (Quantities::needed_field),
    /// is reported at its place in the scene, all in one SceneErrors.
    Simulation(const Scene& scene, const Registry& registry, spdlog::logger& log);
    ~Simulation();

    System& system() { return *system_; }
    const System& system() const { return *system_; }
    Integrator& integrator() { return *integrator_; }
    const Integrator& integrator() const { return *integrator_; }
    Quantities& quantities() { return quantities_; }
    /// Version, scene hash, seed, the plugins that provide the scene's components and the choices
    /// they resolved.
    const RunInfo& info() const { return info_; }
    const Scene& scene() const { return scene_; }
    /// A context for components built later against this simulation (observers).
    Context context(const std::string& name);
    /// The scene's observers, in scene order, for the run that drives them (once).
    std::vector<std::unique_ptr<Observer>> take_observers();

    /// Starts stage `index` of the scene at the current time and logs its pipeline. Estimates the
    /// stable step of the stage's pipeline (stability.hpp) and throws InputError, naming the limit
    /// and the effect that sets it, if the integrator's step is above it, unless told not to.
    StageInfo begin_stage(std::size_t index);
    /// Makes stage `index`, begun at `t_start`, the current one again, for a run resumed within it
    /// (its effects and the system then restore their state from the checkpoint).
    StageInfo resume_stage(std::size_t index, double t_start);
    /// Why stage `index`, once begun, cannot end at rest as its max_speed_at_end asks, or empty: a
    /// load still ramping up at its end (Effect::load_ramp_end). Its end is the scene's, the sum of
    /// the durations so far, so `check`, which steps nothing, judges it as `run` does.
    std::string cannot_end_at_rest(std::size_t index) const;
    /// From when stage `index`, begun, may show how fast it calms: past its middle and every load
    /// ramp; +infinity if it need not end at rest.
    double calm_from(std::size_t index) const;
    /// Whether begin_stage refuses a step above the estimated stable step (default) or only warns.
    void refuse_unstable_steps(bool refuse) { refuse_unstable_ = refuse; }
    /// One integrator step, no longer than max_dt. Throws RunError, naming the step, time, block
    /// and quantity, if the state is no longer finite.
    double step(double max_dt);
    /// Whether the simulated time has reached t_end (to within round-off of the step sum).
    bool reached(double t_end) const;
    /// Steps until t_end (the last step shortened to land on it).
    void advance_to(double t_end);

    /// Every this many steps the state is checked for a runaway: a block farther than
    /// runaway_factor times the slider's size from its reference position stops the run.
    static constexpr long long runaway_check_interval = 8;
    static constexpr double runaway_factor = 10.0;
    /// A scene whose stages need more steps than this is refused before it starts: a step or a
    /// duration off by orders of magnitude (15 days at the baseline's 76,000 steps per second).
    static constexpr double most_steps = 1e11;

    /// What the stable-step estimate of the stage begun last found, in a line ("stable step: dt <= ...").
    const std::string& stable_step_note() const { return stable_step_note_; }

private:
    /// Stage `index`'s end in the scene's time: the sum of the durations so far.
    double stage_end(std::size_t index) const;
    /// The latest Effect::load_ramp_end() of the active effects, and that effect's index in the
    /// pipeline (-infinity if none ramps).
    std::pair<double, std::size_t> latest_load_ramp_end() const;
    void check_bounded() const;
    void check_step_count() const;
    /// Every field a component reads that no effect publishes, at the reader, with its remedy.
    void check_needed_fields(Diagnostics& diagnostics) const;
    /// The scene's component at `path` ("friction", "observers[2]", ...), or null.
    const ComponentSpec* component_at(const std::string& path) const;
    void check_stability(const StageInfo& stage);
    void record_plugin(const ComponentSpec& component, Kind kind);

    const Scene& scene_;
    const Registry& registry_;
    spdlog::logger& log_;
    RunInfo info_;
    Quantities quantities_;
    AuxAllocator aux_;
    std::unique_ptr<BulkModel> bulk_;  // owns the Body the system refers to: declared first
    std::unique_ptr<Integrator> integrator_;
    std::vector<std::unique_ptr<Observer>> observers_;
    std::unique_ptr<System> system_;
    bool refuse_unstable_ = true;
    std::string stable_step_note_;
};

}  // namespace frictionlab
