#pragma once
// The facts every output of a run records, whichever writer writes it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "frictionlab/model/resolved_choice.hpp"
#include "frictionlab/plugins/library.hpp"

namespace frictionlab {

/// Facts every output records (brief: version, scene hash, seed, plugins used).
struct RunInfo {
    std::string framework_version;
    std::filesystem::path scene_file;
    std::string scene_hash;
    std::uint64_t seed = 0;
    std::vector<PluginRecord> plugins;  // the libraries that provide the scene's types
    std::string resolved_scene;         // YAML, every default written out
    ResolvedChoices resolved_choices;   // what the components chose for keys left `auto`
    double loading_start = 0;           // s of simulated time: when loading started (loading_start())
    std::vector<std::string> caveats;   // what the integrator's step misses (Effect::explicit_step_caveat)
};

}  // namespace frictionlab
