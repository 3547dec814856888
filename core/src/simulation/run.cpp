#include "frictionlab/simulation/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <memory>

#include <fmt/format.h>

#include "frictionlab/output/checkpoint_file.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/interrupt_signals.hpp"
#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/output/output_directory.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/simulation/progress_line.hpp"
#include "frictionlab/simulation/run_record.hpp"
#include "frictionlab/simulation/simulation.hpp"
#include "frictionlab/simulation/system.hpp"
#include "calm_watch.hpp"
#include "observer_slot.hpp"
#include "run_checkpoint.hpp"

namespace frictionlab {

namespace {

using Clock = std::chrono::steady_clock;

/// The components of a run that cannot be checkpointed, by their place in the scene. A scene that
/// asks for checkpoints (a `checkpoint:` section) with any is an InputError naming them; one that
/// does not runs without checkpoints.
std::vector<std::string> not_checkpointable(const Scene& scene, const Simulation& sim,
                                            const std::vector<const Observer*>& observers) {
    std::vector<std::string> refusing = sim.system().not_checkpointable();
    if (!sim.integrator().checkpointable()) refusing.push_back("integrator '" + scene.integrator.type + "'");
    for (std::size_t i = 0; i < observers.size(); ++i)
        if (!observers[i]->checkpointable())
            refusing.push_back(fmt::format("{} '{}'", scene.observers[i].path, scene.observers[i].type));
    if (!refusing.empty() && scene.checkpoint.given && scene.checkpoint.wanted())
        throw InputError(
            fmt::format("checkpoint: these components cannot be checkpointed: {}; leave `checkpoint:` out "
                        "of the scene (or set every and wall_every to 0) to run without checkpoints",
                        fmt::join(refusing, ", ")));
    return refusing;
}

/// Drives a Simulation through the scene's stages with its observers and records the run.
class SceneRun {
public:
    SceneRun(const Scene& scene, const Registry& registry, spdlog::logger& log, const RunOptions& options)
        : scene_(scene), log_(log), options_(options), sim_(scene, registry, log) {
        sim_.refuse_unstable_steps(!options.allow_unstable_step);
        for (const auto& caveat : sim_.info().caveats) log_.warn("{}", caveat);
        output_ = scene.output_directory;
        auto observers = sim_.take_observers();
        for (std::size_t i = 0; i < observers.size(); ++i) {
            const ComponentSpec& o = scene.observers[i];
            observers_.push_back({std::move(observers[i]), o.path, o.every, o.every_steps, 0});
        }
        if (std::any_of(observers_.begin(), observers_.end(),
                        [](const ObserverSlot& o) { return o.observer->needs_work_accounting(); }))
            sim_.system().enable_work_accounting();
        check_checkpoints();
        // The first stage is begun (its stable step and its end judged) before anything is written,
        // so that a run refused before its first step, like `check`, leaves no directory behind.
        if (!options.resume) {
            last_stage_ = begin_stage(0);
            prepare_output_directory(scene.output_directory, options.overwrite, {scene.file});
        } else if (!created_by_frictionlab(output_))
            throw InputError(fmt::format("'{}' holds no run of FrictionLab to resume", output_.string()));
    }

    RunSummary execute() {
        RunRecord record{sim_.info(), options_.command_line, options_.overrides, "running", "", {}};
        std::size_t first_stage = 0;
        if (options_.resume) {
            first_stage = resume();
            record.resumed_from_step = sim_.system().step_index();
        }
        record.write(output_);
        const auto start = Clock::now();
        const std::clock_t cpu_start = std::clock();
        const auto summary = [&] {
            return RunSummary{sim_.system().step_index(),
                              sim_.system().evaluations(),
                              sim_.system().time(),
                              std::chrono::duration<double>(Clock::now() - start).count(),
                              static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC,
                              sim_.integrator().statistics(),
                              stages_ended_early_};
        };
        try {
            run_stages(first_stage);
        } catch (const Interrupted& e) {
            const std::string resumable = checkpoint_at_interruption();
            finish_observers();
            record.status = "interrupted";
            record.error = e.what();
            record.summary = summary();
            record.write(output_);
            throw Interrupted(
                fmt::format("{}; the outputs are closed and valid in {}{}", e.what(), output_.string(), resumable),
                e.signal);
        } catch (const std::exception& e) {
            finish_observers();
            record.status = "failed";
            record.error = e.what();
            record.summary = summary();
            record.write(output_);
            const std::string message = fmt::format("{} (outputs so far are in {})", e.what(), output_.string());
            if (dynamic_cast<const InputError*>(&e)) throw InputError(message);  // e.g. a refused time step
            throw RunError(message);
        }
        finish_observers();
        record.status = "done";
        record.summary = summary();
        record.write(output_);
        return record.summary;
    }

private:
    RunView view(const StageInfo& stage) {
        const System& sys = sim_.system();
        return RunView{sys,     sys.body(),  sys.state(), sim_.quantities(), stage, sys.step_index(),
                       output_, sim_.info(), log_,        resuming_};
    }

    void observe_due(const StageInfo& stage, bool all) {
        System& sys = sim_.system();
        // A scheme that lands on observation times (Integrator::steps_to_observations) is observed at
        // them to within round-off; a fixed step observes at the step end nearest the cadence.
        const Integrator& integrator = sim_.integrator();
        const double tolerance = (integrator.steps_to_observations() ? 1e-6 : 0.5) * integrator.nominal_dt();
        for (auto& o : observers_) {
            if (o.seen(sys.step_index(), sys.time())) continue;
            const bool own = all || o.due(sys.time(), sys.step_index(), tolerance);
            if (!own && !o.due_between(sys.time(), tolerance)) continue;
            if (own || o.observer->between_reads_forces()) sys.refresh();
            if (own)
                o.observer->observe(view(stage));
            else
                o.observer->observe_between(view(stage));
            o.advance(sys.time(), tolerance);
            o.last_step = sys.step_index();
            o.last_time = sys.time();
        }
    }

    /// From stage `first`; a resumed run is within it already (its observers begun).
    void run_stages(std::size_t first) {
        ProgressLine progress(log_, options_.live_progress);
        for (std::size_t i = first; i < scene_.stages.size(); ++i) {
            if (i > first || !options_.resume) {
                if (i > 0) {
                    stop_if_asked(last_stage_);
                    last_stage_ = begin_stage(i);
                }
                if (i == 0)
                    for (auto& o : observers_) o.observer->begin(view(last_stage_));
                observe_due(last_stage_, i == 0);
            }
            progress.stage_started();
            run_stage(last_stage_, progress);
            check_end_of_stage(scene_.stages[i], calm_);
        }
        progress.finish();
        observe_due(last_stage_, true);
    }

    void run_stage(const StageInfo& stage, ProgressLine& progress) {
        System& sys = sim_.system();
        const double t_end = stage.t_start + stage.duration;
        calm_ = CalmWatch(sim_.calm_from(static_cast<std::size_t>(stage.index)));
        while (!sim_.reached(t_end)) {
            try {
                double until = sim_.integrator().steps_to_observations() ? std::min(t_end, next_observation()) : t_end;
                if (until <= sys.time()) until = t_end;  // an observation already taken at this time
                sim_.step(until - sys.time());
            } catch (const RunError& e) {
                throw RunError(fmt::format("stage '{}', {}", stage.name, e.what()));
            }
            calm_.observe(sys);
            if (!observers_.empty()) observe_due(stage, false);
            if (ends_early(stage)) break;
            if (checkpoint_due()) write_checkpoint();
            progress.update(stage, sys.time(), sys.step_index());
            stop_if_asked(stage);
        }
    }

    /// Whether an observer ends the stage now (Observer::stage_end); if so, logs and records why.
    bool ends_early(const StageInfo& stage) {
        for (const auto& o : observers_) {
            const std::string why = o.observer->stage_end(stage);
            if (why.empty()) continue;
            const double t = sim_.system().time();
            const std::string end =
                fmt::format("stage '{}' ended at t = {:.9g} s, {:.6g} s before its duration ran out: {}", stage.name, t,
                            stage.t_start + stage.duration - t, why);
            log_.info("{}", end);
            stages_ended_early_.push_back(end);
            return true;
        }
        return false;
    }

    /// Begins stage i; refuses it, as `check` does, if it must end at rest but a load still ramps up then.
    StageInfo begin_stage(std::size_t i) {
        const StageInfo stage = sim_.begin_stage(i);
        if (const std::string why = sim_.cannot_end_at_rest(i); !why.empty()) throw InputError(why);
        return stage;
    }

    /// Between whole steps only: the state, the observers and their files stay consistent.
    void stop_if_asked(const StageInfo& stage) const {
        const int signal = options_.stop_signal ? options_.stop_signal->load(std::memory_order_relaxed) : 0;
        if (signal == 0) return;
        const System& sys = sim_.system();
        throw Interrupted(fmt::format("interrupted by {} after step {} at t = {:.9g} s, in stage '{}'",
                                      InterruptSignals::name(signal), sys.step_index(), sys.time(), stage.name),
                          signal);
    }

    /// The earliest time an observer with a time cadence is due next (+infinity if none is).
    double next_observation() const {
        double next = std::numeric_limits<double>::infinity();
        for (const auto& o : observers_) next = std::min(next, o.next());
        return next;
    }

    void check_end_of_stage(const StageSpec& spec, const CalmWatch& calm) {
        if (!std::isfinite(spec.max_speed_at_end)) return;
        const StageView s = sim_.system().state();
        Index worst = 0;
        const double speed = top_speed(s, &worst);
        if (speed > spec.max_speed_at_end) {
            const std::string advice = calm.advice(s.t, speed, spec.max_speed_at_end);
            throw RunError(
                fmt::format("stage '{}' ended at t = {:.9g} s with block {} moving at {:.3g} m/s, above "
                            "its max_speed_at_end of {:.3g} m/s ({})",
                            spec.name, s.t, worst, speed, spec.max_speed_at_end,
                            advice.empty() ? "settle longer or damp more" : advice));
        }
        log_.info("stage '{}' ended at rest: max speed {:.3g} m/s (limit {:.3g} m/s)", spec.name, speed,
                  spec.max_speed_at_end);
    }

    /// Which components cannot be checkpointed; a scene that asks for checkpoints then is refused,
    /// one that does not (the default cadence) runs without them, saying so.
    void check_checkpoints() {
        std::vector<const Observer*> observers;
        for (const auto& o : observers_) observers.push_back(o.observer.get());
        const auto refusing = not_checkpointable(scene_, sim_, observers);
        if (refusing.empty()) {
            checkpoints_possible_ = true;
            schedule_next_checkpoint();
            return;
        }
        const std::string who = fmt::format("{}", fmt::join(refusing, ", "));
        if (options_.resume) throw InputError(fmt::format("cannot resume: {} cannot be checkpointed", who));
        log_.info("no checkpoints in this run: {} cannot be checkpointed", who);
    }

    bool checkpoint_due() const {
        if (!checkpoints_possible_) return false;
        const CheckpointSpec& c = scene_.checkpoint;
        if (c.every > 0 && sim_.system().time() >= next_checkpoint_time_) return true;
        // The clock is read every 256 steps only: a wall-clock cadence needs no finer look, and a step
        // of the paper's lattice costs ~15 us.
        return c.wall_every > 0 && sim_.system().step_index() % 256 == 0 &&
               std::chrono::duration<double>(Clock::now() - last_checkpoint_wall_).count() >= c.wall_every;
    }

    /// The first multiple of `every` after the current time, and a wall-clock period from now.
    void schedule_next_checkpoint() {
        const double every = scene_.checkpoint.every;
        if (every > 0) next_checkpoint_time_ = (std::floor(sim_.system().time() / every) + 1) * every;
        last_checkpoint_wall_ = Clock::now();
    }

    void write_checkpoint() {
        const System& sys = sim_.system();
        RunCheckpoint c = RunCheckpoint::identity_of(sim_.info());
        c.stage = static_cast<std::uint64_t>(last_stage_.index);
        c.stage_start = last_stage_.t_start;
        c.system = archived([&](StateOut& out) { sys.save_state(out); });
        c.quantities = archived([&](StateOut& out) { sim_.quantities().save_state(out); });
        c.integrator = archived_state(sim_.integrator());
        for (const auto& o : observers_)
            c.observers.push_back({o.next_time, o.last_step, o.last_time, o.finer_next, archived_state(*o.observer)});
        c.outputs = output_lengths(output_);
        write_checkpoint_file(output_, c.payload());
        schedule_next_checkpoint();
        log_.debug("checkpoint at step {}, t = {:.9g} s", sys.step_index(), sys.time());
    }

    /// After SIGINT or SIGTERM: a checkpoint of the state reached, and how to go on from it.
    std::string checkpoint_at_interruption() {
        if (!checkpoints_possible_)
            return "; this run cannot be resumed (it has components that cannot be checkpointed)";
        try {
            write_checkpoint();
        } catch (const std::exception& e) {
            return fmt::format("; no checkpoint could be written ({})", e.what());
        }
        return fmt::format("; continue it with: frictionlab run --resume {}", output_.string());
    }

    /// Puts the run back where its last intact checkpoint left it; returns the stage to go on in.
    std::size_t resume() {
        const RunCheckpoint c = RunCheckpoint::from_payload(
            read_checkpoint_file(output_, [&](const std::string& w) { log_.warn("{}", w); }));
        c.check_same_run(RunCheckpoint::identity_of(sim_.info()));
        if (c.stage >= scene_.stages.size() || c.observers.size() != observers_.size())
            throw RunError("the checkpoint does not fit this scene's stages or observers");
        restore_output_lengths(output_, c.outputs);
        last_stage_ = sim_.resume_stage(c.stage, c.stage_start);
        restore_archived(c.system, "the system", [&](StateIn& in) { sim_.system().restore_state(in); });
        restore_archived(c.quantities, "the published quantities",
                         [&](StateIn& in) { sim_.quantities().restore_state(in); });
        restore_archived_state(sim_.integrator(), c.integrator, "integrator '" + scene_.integrator.type + "'");
        resuming_ = true;
        for (std::size_t i = 0; i < observers_.size(); ++i) {
            auto& o = observers_[i];
            o.observer->begin(view(last_stage_));
            o.next_time = c.observers[i].next_time;
            o.last_step = c.observers[i].last_step;
            o.last_time = c.observers[i].last_time;
            o.finer_next = c.observers[i].finer_next;
            restore_archived_state(*o.observer, c.observers[i].state, o.path);
            o.observer->resumed(view(last_stage_));
        }
        resuming_ = false;
        const System& sys = sim_.system();
        schedule_next_checkpoint();
        log_.info("resumed from the checkpoint at step {}, t = {:.9g} s, in stage '{}'", sys.step_index(), sys.time(),
                  last_stage_.name);
        return c.stage;
    }

    void finish_observers() {
        for (auto& o : observers_) {
            try {
                o.observer->end(view(last_stage_));
            } catch (const std::exception& e) {
                log_.error("observer {} could not finish its outputs: {}", o.path, e.what());
            }
        }
    }

    const Scene& scene_;
    spdlog::logger& log_;
    RunOptions options_;
    Simulation sim_;
    std::filesystem::path output_;
    std::vector<ObserverSlot> observers_;  // after sim_: destroyed first
    StageInfo last_stage_;
    std::vector<std::string> stages_ended_early_;  // Observer::stage_end, as run.yaml records it
    CalmWatch calm_;                               // of the stage running
    bool resuming_ = false;                        // observers are being begun again on a resumed run
    bool checkpoints_possible_ = false;
    double next_checkpoint_time_ = 0;
    Clock::time_point last_checkpoint_wall_ = Clock::now();
};

}  // namespace

RunInfo check_scene_builds(const Scene& scene, const Registry& registry, spdlog::logger& log) {
    Simulation sim(scene, registry, log);
    const auto observers = sim.take_observers();
    std::vector<const Observer*> built;
    for (const auto& o : observers) built.push_back(o.get());
    not_checkpointable(scene, sim, built);
    return sim.info();
}

RunSummary run_scene(const Scene& scene, const Registry& registry, spdlog::logger& log, const RunOptions& options) {
    return SceneRun(scene, registry, log, options).execute();
}

}  // namespace frictionlab
