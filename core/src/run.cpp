#include "frictionlab/run.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <limits>
#include <memory>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "frictionlab/errors.hpp"
#include "frictionlab/json.hpp"
#include "frictionlab/output_directory.hpp"
#include "frictionlab/registry.hpp"
#include "frictionlab/simulation.hpp"
#include "frictionlab/system.hpp"

namespace frictionlab {

namespace {

using Clock = std::chrono::steady_clock;

/// Writes a file so that readers never see a half-written one: temporary file, then rename.
void write_atomically(const std::filesystem::path& file, const std::string& text) {
    const auto tmp = std::filesystem::path(file).concat(".tmp");
    {
        std::ofstream out(tmp, std::ios::trunc);
        out << text;
        if (!out) throw RunError("cannot write " + tmp.string());
    }
    std::filesystem::rename(tmp, file);
}

/// One observer with its cadence (design.md §1.7: an observer costs in proportion to its cadence).
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
        if (every > 0)
            while (next_time <= t + tolerance) next_time += every;
    }
};

/// The run's record: what, with what, how far. Rewritten at start and end (and on failure).
struct RunRecord {
    const RunInfo& info;
    std::string status = "running";
    std::string error;
    RunSummary summary;

    void write(const std::filesystem::path& dir) const {
        YAML::Emitter y;
        y.SetDoublePrecision(12);
        y << YAML::BeginMap;
        y << YAML::Key << "framework" << YAML::Value << "frictionlab";
        y << YAML::Key << "version" << YAML::Value << info.framework_version;
        y << YAML::Key << "status" << YAML::Value << status;
        if (!error.empty()) y << YAML::Key << "error" << YAML::Value << error;
        y << YAML::Key << "scene_file" << YAML::Value << info.scene_file.string();
        y << YAML::Key << "scene_hash" << YAML::Value << info.scene_hash;
        y << YAML::Key << "seed" << YAML::Value << info.seed;
        y << YAML::Key << "steps" << YAML::Value << summary.steps;
        y << YAML::Key << "evaluations" << YAML::Value << summary.evaluations;
        y << YAML::Key << "simulated_time" << YAML::Value << summary.simulated_time;
        y << YAML::Key << "wall_seconds" << YAML::Value << summary.wall_seconds;
        y << YAML::Key << "cpu_seconds" << YAML::Value << summary.cpu_seconds;
        if (!summary.integrator_statistics.empty()) {
            y << YAML::Key << "integrator_statistics" << YAML::Value << YAML::BeginMap;
            for (const auto& [name, value] : summary.integrator_statistics) y << YAML::Key << name << YAML::Value << value;
            y << YAML::EndMap;
        }
        y << YAML::Key << "plugins" << YAML::Value << YAML::BeginSeq;
        for (const auto& p : info.plugins)
            y << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << p.name << YAML::Key
              << "version" << YAML::Value << p.version << YAML::Key << "file" << YAML::Value
              << p.file.filename().string() << YAML::EndMap;
        y << YAML::EndSeq;
        y << YAML::Key << "scene" << YAML::Value << YAML::Load(info.resolved_scene);
        y << YAML::EndMap;
        write_atomically(dir / "run.yaml", std::string(y.c_str()) + "\n");
        write_atomically(dir / "run.json", to_json(YAML::Load(y.c_str())) + "\n");
    }

    static std::string to_json(const YAML::Node& n) {
        switch (n.Type()) {
            case YAML::NodeType::Map: {
                std::string out = "{";
                for (auto it = n.begin(); it != n.end(); ++it)
                    out += (out.size() > 1 ? ", " : "") + json_quote(it->first.Scalar()) + ": " + to_json(it->second);
                return out + "}";
            }
            case YAML::NodeType::Sequence: {
                std::string out = "[";
                for (std::size_t i = 0; i < n.size(); ++i) out += (i ? ", " : "") + to_json(n[i]);
                return out + "]";
            }
            case YAML::NodeType::Scalar: return scalar_json(n);
            default: return "null";
        }
    }
    static std::string scalar_json(const YAML::Node& n) {
        const std::string& s = n.Scalar();
        if (n.Tag() != "!") {  // plain scalar: a number or boolean stays one
            if (s == "true" || s == "false") return s;
            char* end = nullptr;
            const double v = std::strtod(s.c_str(), &end);
            if (!s.empty() && end == s.c_str() + s.size() && std::isfinite(v)) return s;
        }
        return json_quote(s);
    }
};

/// Live progress on a terminal, periodic log lines otherwise.
class Progress {
public:
    Progress(spdlog::logger& log, bool live) : log_(log), live_(live), start_(Clock::now()), last_(start_) {}

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
        if (live_) std::fprintf(stderr, "\r%-100s", line.c_str()), std::fflush(stderr);
        else log_.info(line);
        last_ = now;
        last_steps_ = steps;
    }
    void stage_started() { stage_wall_ = std::chrono::duration<double>(Clock::now() - start_).count(); }
    void finish() {
        if (live_) std::fprintf(stderr, "\r%-100s\r", ""), std::fflush(stderr);
    }

private:
    spdlog::logger& log_;
    bool live_;
    Clock::time_point start_, last_;
    long long last_steps_ = 0;
    double stage_wall_ = 0;
};

/// Drives a Simulation through the scene's stages with its observers and records the run.
class SceneRun {
public:
    SceneRun(const Scene& scene, const Registry& registry, spdlog::logger& log, const RunOptions& options)
        : scene_(scene), registry_(registry), log_(log), options_(options), sim_(scene, registry, log) {
        sim_.refuse_unstable_steps(!options.allow_unstable_step);
        // After the components accepted their parameters, so a refusal leaves no directory behind.
        prepare_output_directory(scene.output_directory, options.overwrite, {scene.file});
        output_ = scene.output_directory;
        for (const auto& o : scene.observers) {
            auto observer = located_in_scene(
                o, [&] { return registry.create<Observer>(o.type, o.values, sim_.context(o.path)); });
            observers_.push_back({std::move(observer), o.path, o.every, o.every_steps, 0});
        }
        if (std::any_of(observers_.begin(), observers_.end(),
                        [](const ObserverSlot& o) { return o.observer->needs_work_accounting(); }))
            sim_.system().enable_work_accounting();
    }

    RunSummary execute() {
        RunRecord record{sim_.info(), "running", "", {}};
        record.write(output_);
        const auto start = Clock::now();
        const std::clock_t cpu_start = std::clock();
        const auto summary = [&] {
            return RunSummary{sim_.system().step_index(), sim_.system().evaluations(), sim_.system().time(),
                              std::chrono::duration<double>(Clock::now() - start).count(),
                              static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC,
                              sim_.integrator().statistics()};
        };
        try {
            run_stages();
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
        return RunView{sys, sys.body(), sys.state(), sim_.quantities(), stage, sys.step_index(), output_, sim_.info(),
                       log_};
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
        }
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
            throw RunError(fmt::format("stage '{}' ended at t = {:.9g} s with block {} moving at {:.3g} m/s, above "
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
    const Registry& registry_;
    spdlog::logger& log_;
    RunOptions options_;
    Simulation sim_;
    std::filesystem::path output_;
    std::vector<ObserverSlot> observers_;  // after sim_: destroyed first
    StageInfo last_stage_;
};

}  // namespace

RunSummary run_scene(const Scene& scene, const Registry& registry, spdlog::logger& log, const RunOptions& options) {
    return SceneRun(scene, registry, log, options).execute();
}

}  // namespace frictionlab
