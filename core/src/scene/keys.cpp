#include "frictionlab/scene/keys.hpp"

#include <limits>

namespace frictionlab::detail {

ParamInfo key(std::string name, ValueType type, ParamValue default_value, std::string doc, std::string unit) {
    ParamInfo info;
    info.key = std::move(name);
    info.type = type;
    info.default_value = std::move(default_value);
    info.doc = std::move(doc);
    info.unit = std::move(unit);
    return info;
}

ParamInfo required(ParamInfo info) {
    info.required = true;
    return info;
}

ParamInfo greater_than(ParamInfo info, double bound) {
    info.greater_than = bound;
    return info;
}

ParamInfo at_least(ParamInfo info, double bound) {
    info.at_least = bound;
    return info;
}


const std::vector<ParamInfo>& top_level_params() {
    static const std::vector<ParamInfo> params = {
        key("title", ValueType::string, std::string(), "A line describing the scene, for the run's records."),
        at_least(key("seed", ValueType::integer, std::int64_t{0}, "Seed of every random draw of the run."), 0),
        required(key("output", ValueType::string, std::string(),
                     "Output directory, relative to the working directory.")),
    };
    return params;
}

const std::vector<std::string>& top_level_sections() {
    static const std::vector<std::string> keys = {"plugin_paths", "bulk",   "friction",  "loaders",
                                                  "integrator",   "stages", "observers"};
    return keys;
}

const ParamInfo& plugin_paths_param() {
    static const ParamInfo info = key("plugin_paths", ValueType::string_list, std::vector<std::string>(),
                                      "Folders searched for plugins, relative to the scene file's folder.");
    return info;
}

const std::vector<ParamInfo>& stage_params() {
    static const std::vector<ParamInfo> params = {
        required(key("name", ValueType::string, std::string(), "Name of the stage, lower_snake_case, unique.")),
        required(greater_than(key("duration", ValueType::real, 0.0, "Simulated time the stage lasts.", "s"), 0)),
        key("friction_events", ValueType::boolean, true,
            "Whether junctions may change state (false while settling)."),
        greater_than(key("max_speed_at_end", ValueType::real, std::numeric_limits<double>::infinity(),
                         "Largest node speed allowed at the end of the stage; absent: no check.", "m/s"),
                     0),
    };
    return params;
}

const std::vector<ParamInfo>& scene_level_params(Kind kind) {
    static const std::vector<ParamInfo> none;
    static const std::vector<ParamInfo> loader = {
        key("stages", ValueType::string_list, std::vector<std::string>(),
            "The stages this loader acts in; absent: all stages."),
    };
    static const std::vector<ParamInfo> observer = {
        greater_than(key("every", ValueType::real, 0.0, "Cadence in simulated time.", "s"), 0),
        at_least(key("every_steps", ValueType::integer, std::int64_t{0}, "Cadence in integrator steps."), 1),
    };
    if (kind == Kind::loader) return loader;
    if (kind == Kind::observer) return observer;
    return none;
}

}  // namespace frictionlab::detail
