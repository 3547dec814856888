#include "frictionlab/simulation/run.hpp"

#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>

#include <fmt/format.h>
#include <spdlog/details/null_mutex.h>
#include <spdlog/sinks/base_sink.h>
#include <yaml-cpp/yaml.h>

#include "frictionlab/output/atomic_file.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/output/output_directory.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/simulation/simulation.hpp"
#include "frictionlab/simulation/system.hpp"
#include "scene/emit.hpp"

namespace frictionlab {

namespace {

using Clock = std::chrono::steady_clock;

/// One observer with its cadence: an observer costs in proportion to its cadence.
struct ObserverSlot {
    std::unique_ptr<Observer> observer;
    std::string path;
    double every = 0;
    long long every_steps = 0;
    double next_time = 0;
    long long last_step = -1;  // an observer sees each step at most once (stage ends, run end)

    bool due(double t, long long step, double tolerance) const {
        if (every_steps > 0) return step % every_steps == 0;
        return t >= next_time - tolerance;
    }
    /// Schedules the next observation after one at t; `tolerance` must be the one due() used, or an
    /// observation taken early by up to it would be repeated one step later.
    void advance(double t, double tolerance) {
        if (!(every > 0)) return;
        // Far behind (a cadence much finer than the step): jump, rather than add `every` millions
        // of times a step; the scene check refuses a cadence too fine to move the sum at all.
        if (next_time + 1024 * every <= t + tolerance)
            next_time += std::floor((t + tolerance - next_time) / every) * every;
        while (next_time <= t + tolerance) {
            const double next = next_time + every;
            next_time = next > next_time ? next : std::nextafter(next_time, INFINITY);
        }
    }
};

/// The run's record: what, with what, how far. Rewritten at start and end (and on failure).
struct RunRecord {
    const RunInfo& info;
    const RunOptions& options;
    std::string status = "running";
    std::string error;  // why it failed, or what interrupted it
    RunSummary summary;

    /// Atomically; when the disk is too full even for that (the usual reason a run fails late), in
    /// place, within the room set aside after the previous write, so the record never stays `running`.
    void write(const std::filesystem::path& dir) const {
        const std::string yaml = text();
        const auto file = dir / "run.yaml";
        try {
            write_file_atomically(file, yaml);
        } catch (const RunError&) {
            if (!std::filesystem::exists(file)) throw;
            overwrite_in_place(file, yaml);
        }
        reserve_space(file, room_for_the_last_record);
    }
    static constexpr long room_for_the_last_record = 16 * 1024;

    std::string text() const {
        YAML::Emitter y;
        y.SetDoublePrecision(12);
        y << YAML::BeginMap;
        y << YAML::Key << "framework" << YAML::Value << "frictionlab";
        y << YAML::Key << "version" << YAML::Value << info.framework_version;
        y << YAML::Key << "status" << YAML::Value << status;
        if (!error.empty())
            y << YAML::Key << (status == "interrupted" ? "interrupted_by" : "error") << YAML::Value << error;
        y << YAML::Key << "scene_file" << YAML::Value << info.scene_file.string();
        y << YAML::Key << "command_line" << YAML::Value << YAML::Flow << options.command_line;
        y << YAML::Key << "overrides" << YAML::Value << YAML::Flow << options.overrides;
        y << YAML::Key << "scene_hash" << YAML::Value << info.scene_hash;
        y << YAML::Key << "seed" << YAML::Value << info.seed;
        y << YAML::Key << "steps" << YAML::Value << summary.steps;
        y << YAML::Key << "evaluations" << YAML::Value << summary.evaluations;
        y << YAML::Key << "simulated_time" << YAML::Value << summary.simulated_time;
        y << YAML::Key << "wall_seconds" << YAML::Value << summary.wall_seconds;
        y << YAML::Key << "cpu_seconds" << YAML::Value << summary.cpu_seconds;
        if (!summary.integrator_statistics.empty()) {
            y << YAML::Key << "integrator_statistics" << YAML::Value << YAML::BeginMap;
            for (const auto& [name, value] : summary.integrator_statistics)
                y << YAML::Key << name << YAML::Value << value;
            y << YAML::EndMap;
        }
        y << YAML::Key << "plugins" << YAML::Value << YAML::BeginSeq;
        for (const auto& p : info.plugins)
            y << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << p.name << YAML::Key << "version"
              << YAML::Value << p.version << YAML::Key << "file" << YAML::Value << p.file.string() << YAML::Key
              << "fnv1a_64" << YAML::Value << p.fingerprint << YAML::EndMap;
        y << YAML::EndSeq;
        y << YAML::Key << "scene" << YAML::Value << YAML::Load(info.resolved_scene);
        y << YAML::EndMap;
        return std::string(y.c_str()) + "\n";
    }
};

/// Clears the live progress line before a log line is printed over it; the line is drawn again at
/// the next update.
class ProgressLineEraser : public spdlog::sinks::base_sink<spdlog::details::null_mutex> {
public:
    bool shown = false;

    void erase() {
        if (shown) std::fprintf(stderr, "\r%-100s\r", ""), std::fflush(stderr);
        shown = false;
    }

protected:
    void sink_it_(const spdlog::details::log_msg&) override { erase(); }
    void flush_() override {}
};

/// Live progress on a terminal, periodic log lines otherwise.
class Progress {
public:
    Progress(spdlog::logger& log, bool live) : log_(log), live_(live), start_(Clock::now()), last_(start_) {
        // First among the logger's sinks, so the line is gone before any of them prints.
        if (live_) log_.sinks().insert(log_.sinks().begin(), eraser_);
    }
    ~Progress() {
        finish();
        auto& sinks = log_.sinks();
        sinks.erase(std::remove(sinks.begin(), sinks.end(), eraser_), sinks.end());
    }
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    void update(const StageInfo& stage, double t, long long steps) {
        const auto now = Clock::now();
        const double since = std::chrono::duration<double>(now - last_).count();
        if (since < (live_ ? 0.25 : 10.0)) return;
        const double wall = std::chrono::duration<double>(now - start_).count();
        const double done = std::clamp((t - stage.t_start) / stage.duration, 0.0, 1.0);
        const double rate = static_cast<double>(steps - last_steps_) / since;
        const double eta = done > 0 ? (1 - done) / done * (wall - stage_wall_) : 0;
        const std::string line = fmt::format("stage {} ({}): t = {:.6g} s, {:5.1f} %, {:.3g} steps/s, ETA {:.0f} s",
                                             stage.index + 1, stage.name, t, 100 * done, rate, eta);
        if (live_)
            std::fprintf(stderr, "\r%-100s", line.c_str()), std::fflush(stderr), eraser_->shown = true;
        else
            log_.info(line);
        last_ = now;
        last_steps_ = steps;
    }
    void stage_started() { stage_wall_ = std::chrono::duration<double>(Clock::now() - start_).count(); }
    void finish() { eraser_->erase(); }

private:
    spdlog::logger& log_;
    std::shared_ptr<ProgressLineEraser> eraser_ = std::make_shared<ProgressLineEraser>();
    bool live_;
    Clock::time_point start_, last_;
    long long last_steps_ = 0;
    double stage_wall_ = 0;
};

/// Drives a Simulation through the scene's stages with its observers and records the run.
class SceneRun {
public:
    SceneRun(const Scene& scene, const Registry& registry, spdlog::logger& log, const RunOptions& options)
        : scene_(scene), log_(log), options_(options), sim_(scene, registry, log) {
        sim_.refuse_unstable_steps(!options.allow_unstable_step);
        // After the components accepted their parameters, so a refusal leaves no directory behind.
        prepare_output_directory(scene.output_directory, options.overwrite, {scene.file});
        output_ = scene.output_directory;
        for (const auto& o : scene.observers) {
            auto observer =
                located_in_scene(o, [&] { return registry.create<Observer>(o.type, o.values, sim_.context(o.path)); });
            observers_.push_back({std::move(observer), o.path, o.every, o.every_steps, 0});
        }
        if (std::any_of(observers_.begin(), observers_.end(),
                        [](const ObserverSlot& o) { return o.observer->needs_work_accounting(); }))
            sim_.system().enable_work_accounting();
    }

    RunSummary execute() {
        RunRecord record{sim_.info(), options_, "running", "", {}};
        record.write(output_);
        const auto start = Clock::now();
        const std::clock_t cpu_start = std::clock();
        const auto summary = [&] {
            return RunSummary{sim_.system().step_index(),
                              sim_.system().evaluations(),
                              sim_.system().time(),
                              std::chrono::duration<double>(Clock::now() - start).count(),
                              static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC,
                              sim_.integrator().statistics()};
        };
        try {
            run_stages();
        } catch (const Interrupted& e) {
            finish_observers();
            record.status = "interrupted";
            record.error = e.what();
            record.summary = summary();
            record.write(output_);
            throw Interrupted(fmt::format("{}; the outputs are closed and valid in {}", e.what(), output_.string()),
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
        record.status = "completed";
        record.summary = summary();
        record.write(output_);
        return record.summary;
    }

private:
    RunView view(const StageInfo& stage) {
        const System& sys = sim_.system();
        return RunView{sys,     sys.body(),  sys.state(), sim_.quantities(), stage, sys.step_index(),
                       output_, sim_.info(), log_};
    }

    void observe_due(const StageInfo& stage, bool all) {
        System& sys = sim_.system();
        // A scheme that lands on observation times (Integrator::steps_to_observations) is observed at
        // them to within round-off; a fixed step observes at the step end nearest the cadence.
        const Integrator& integrator = sim_.integrator();
        const double tolerance = (integrator.steps_to_observations() ? 1e-6 : 0.5) * integrator.nominal_dt();
        bool refreshed = false;
        for (auto& o : observers_) {
            if (o.last_step == sys.step_index() || (!all && !o.due(sys.time(), sys.step_index(), tolerance))) continue;
            if (!refreshed) sys.refresh(), refreshed = true;
            o.observer->observe(view(stage));
            o.advance(sys.time(), tolerance);
            o.last_step = sys.step_index();
        }
    }

    void run_stages() {
        Progress progress(log_, options_.live_progress);
        for (std::size_t i = 0; i < scene_.stages.size(); ++i) {
            if (i > 0) stop_if_asked(last_stage_);
            last_stage_ = sim_.begin_stage(i);
            if (i == 0)
                for (auto& o : observers_) o.observer->begin(view(last_stage_));
            observe_due(last_stage_, i == 0);
            progress.stage_started();
            run_stage(last_stage_, progress);
            check_end_of_stage(scene_.stages[i]);
        }
        progress.finish();
        observe_due(last_stage_, true);
    }

    void run_stage(const StageInfo& stage, Progress& progress) {
        System& sys = sim_.system();
        const double t_end = stage.t_start + stage.duration;
        const bool to_observations = sim_.integrator().steps_to_observations();
        while (!sim_.reached(t_end)) {
            try {
                double until = to_observations ? std::min(t_end, next_observation()) : t_end;
                if (until <= sys.time()) until = t_end;  // an observation already taken at this time
                sim_.step(until - sys.time());
            } catch (const RunError& e) {
                throw RunError(fmt::format("stage '{}', {}", stage.name, e.what()));
            }
            if (!observers_.empty()) observe_due(stage, false);
            progress.update(stage, sys.time(), sys.step_index());
            stop_if_asked(stage);
        }
    }

    /// Between whole steps only: the state, the observers and their files stay consistent.
    void stop_if_asked(const StageInfo& stage) const {
        const int signal = options_.stop_signal ? options_.stop_signal->load(std::memory_order_relaxed) : 0;
        if (signal == 0) return;
        const System& sys = sim_.system();
        throw Interrupted(fmt::format("interrupted by {} after step {} at t = {:.9g} s, in stage '{}'",
                                      signal == SIGTERM  ? "SIGTERM"
                                      : signal == SIGINT ? "SIGINT"
                                                         : "a signal",
                                      sys.step_index(), sys.time(), stage.name),
                          signal);
    }

    /// The earliest time an observer with a time cadence is due next (+infinity if none is).
    double next_observation() const {
        double next = std::numeric_limits<double>::infinity();
        for (const auto& o : observers_)
            if (o.every > 0) next = std::min(next, o.next_time);
        return next;
    }

    void check_end_of_stage(const StageSpec& spec) {
        if (!std::isfinite(spec.max_speed_at_end)) return;
        const StageView s = sim_.system().state();
        Index worst = 0;
        const double speed = (s.vx.square() + s.vz.square()).sqrt().maxCoeff(&worst);
        if (speed > spec.max_speed_at_end)
            throw RunError(
                fmt::format("stage '{}' ended at t = {:.9g} s with block {} moving at {:.3g} m/s, above "
                            "its max_speed_at_end of {:.3g} m/s (settle longer or damp more)",
                            spec.name, s.t, worst, speed, spec.max_speed_at_end));
        log_.info("stage '{}' ended at rest: max speed {:.3g} m/s (limit {:.3g} m/s)", spec.name, speed,
                  spec.max_speed_at_end);
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
};

}  // namespace

void check_scene_builds(const Scene& scene, const Registry& registry, spdlog::logger& log) {
    Simulation sim(scene, registry, log);
    for (const auto& o : scene.observers)
        located_in_scene(o, [&] { return registry.create<Observer>(o.type, o.values, sim.context(o.path)); });
}

RunSummary run_scene(const Scene& scene, const Registry& registry, spdlog::logger& log, const RunOptions& options) {
    return SceneRun(scene, registry, log, options).execute();
}

}  // namespace frictionlab
