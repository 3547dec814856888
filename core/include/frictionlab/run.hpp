#pragma once
// Runs a validated scene: builds the components through the registry, assembles the pipeline,
// steps through the stages, drives the observers at their cadence and records run metadata.
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <spdlog/logger.h>

#include "frictionlab/body.hpp"
#include "frictionlab/plugin_library.hpp"
#include "frictionlab/quantities.hpp"
#include "frictionlab/scene.hpp"
#include "frictionlab/stage.hpp"
#include "frictionlab/state.hpp"

namespace frictionlab {

class Registry;
class System;

/// Facts every output records (brief: version, scene hash, seed, plugins used).
struct RunInfo {
    std::string framework_version;
    std::filesystem::path scene_file;
    std::string scene_hash;
    std::uint64_t seed = 0;
    std::vector<PluginRecord> plugins;  // the libraries that provide the scene's types
    std::string resolved_scene;         // YAML, every default written out
};

/// What an observer sees: read-only, at the accepted state, after System::refresh().
struct RunView {
    const System& system;
    const Body& body;
    StageView state;
    const Quantities& quantities;
    const StageInfo& stage;
    long long step;
    const std::filesystem::path& output_directory;
    const RunInfo& info;
    spdlog::logger& log;
};

struct RunOptions {
    bool overwrite = false;            // replace an existing output directory that FrictionLab created
    bool allow_unstable_step = false;  // run a time step above the estimated stable one
    bool live_progress = false;        // one live progress line (terminal); else periodic log lines
};

struct RunSummary {
    long long steps = 0;
    long long evaluations = 0;  // derivative evaluations of the time stepping
    double simulated_time = 0, wall_seconds = 0;
    double cpu_seconds = 0;  // processor time of the run: what it costs, whatever else shares the machine
    std::vector<std::pair<std::string, double>> integrator_statistics;  // Integrator::statistics()
};

/// Throws RunError on failure, after every observer has closed its outputs.
RunSummary run_scene(const Scene& scene, const Registry& registry, spdlog::logger& log, const RunOptions& options);

/// The framework version, e.g. "0.1.0".
std::string framework_version();

}  // namespace frictionlab
