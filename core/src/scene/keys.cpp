#include "frictionlab/scene/keys.hpp"

#include <cstdint>
#include <limits>

namespace frictionlab::detail {

// Each group of keys is declared on a struct of its own, with the builder plugins use, so that the
// format's keys get the same types, defaults (the member initialisers), bounds and docs.
namespace {

struct Header {
    std::string title;
    std::int64_t seed = 0;
    std::string output;
};

struct PluginPaths {
    std::vector<std::string> plugin_paths;
};

struct Stage {
    std::string name;
    double duration = 0;
    bool friction_events = true;
    double max_speed_at_end = std::numeric_limits<double>::infinity();
};

struct CheckpointKeys {
    double every = 0;
    double wall_every = 600;
};

struct LoaderKeys {
    std::vector<std::string> stages;
};

struct ObserverKeys {
    double every = 0;
    std::int64_t every_steps = 0;
};

}  // namespace

const std::vector<ParamInfo>& top_level_params() {
    static const ParamSpec<Header> spec = [] {
        ParamSpec<Header> s;
        s.add("title", &Header::title, "A line describing the scene, for the run's records.");
        s.add("seed", &Header::seed, "Seed of every random draw of the run.").at_least(0);
        s.add("output", &Header::output,
              "Output directory, relative to the working directory; may be left out when the command gives one "
              "(run or check -o DIR).")
            .required();
        return s;
    }();
    return spec.params();
}

const std::vector<std::string>& top_level_sections() {
    static const std::vector<std::string> keys = {"plugin_paths", "bulk",   "friction",  "loaders",
                                                  "integrator",   "stages", "observers", "checkpoint"};
    return keys;
}

const ParamInfo& plugin_paths_param() {
    static const ParamSpec<PluginPaths> spec = [] {
        ParamSpec<PluginPaths> s;
        s.add("plugin_paths", &PluginPaths::plugin_paths,
              "Folders searched for plugins, relative to the scene file's folder.");
        return s;
    }();
    return spec.params().front();
}

const std::vector<ParamInfo>& checkpoint_params() {
    static const ParamSpec<CheckpointKeys> spec = [] {
        ParamSpec<CheckpointKeys> s;
        s.add("every", &CheckpointKeys::every,
              "Simulated time between checkpoints (run --resume continues from the last); 0: none on this clock.")
            .unit("s")
            .at_least(0);
        s.add("wall_every", &CheckpointKeys::wall_every,
              "Wall-clock time between checkpoints, so that a long run is protected without asking; 0: none on "
              "this clock. A run interrupted by SIGINT or SIGTERM writes one in any case.")
            .unit("s")
            .at_least(0);
        return s;
    }();
    return spec.params();
}

const std::vector<ParamInfo>& stage_params() {
    static const ParamSpec<Stage> spec = [] {
        ParamSpec<Stage> s;
        s.add("name", &Stage::name, "Name of the stage, lower_snake_case, unique.").required();
        s.add("duration", &Stage::duration, "Simulated time the stage lasts.").unit("s").greater_than(0).required();
        s.add("friction_events", &Stage::friction_events, "Whether junctions may change state (false while settling).");
        s.add("max_speed_at_end", &Stage::max_speed_at_end,
              "Largest node speed allowed at the end of the stage; absent: no check.")
            .unit("m/s")
            .greater_than(0);
        return s;
    }();
    return spec.params();
}

const std::vector<ParamInfo>& scene_level_params(Kind kind) {
    static const std::vector<ParamInfo> none;
    static const ParamSpec<LoaderKeys> loader = [] {
        ParamSpec<LoaderKeys> s;
        s.add("stages", &LoaderKeys::stages, "The stages this loader acts in; absent: all stages.");
        return s;
    }();
    static const ParamSpec<ObserverKeys> observer = [] {
        ParamSpec<ObserverKeys> s;
        s.add("every", &ObserverKeys::every, "Cadence in simulated time.").unit("s").greater_than(0);
        s.add("every_steps", &ObserverKeys::every_steps, "Cadence in integrator steps.").at_least(1);
        return s;
    }();
    if (kind == Kind::loader) return loader.params();
    if (kind == Kind::observer) return observer.params();
    return none;
}

}  // namespace frictionlab::detail
