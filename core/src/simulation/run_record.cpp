#include "frictionlab/base/parallel_chunks.hpp"
#include "frictionlab/simulation/run_record.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/output/atomic_file.hpp"
#include "frictionlab/output/checkpoint_file.hpp"
#include "frictionlab/output/output_directory.hpp"
#include "frictionlab/output/provenance.hpp"

namespace frictionlab {

void RunRecord::write(const std::filesystem::path& dir) const {
    const std::string yaml = text();
    const auto file = dir / "run.yaml";
    try {
        write_file_atomically(file, yaml, Durability::durable);  // a resume reads it
    } catch (const RunError&) {
        if (!std::filesystem::exists(file)) throw;
        overwrite_in_place(file, yaml);
    }
    reserve_space(file, room_for_the_last_record);
}

std::string RunRecord::text() const {
    YAML::Emitter y;
    y.SetDoublePrecision(12);
    y << YAML::BeginMap;
    const auto entry = [&](const auto& key, const auto& value) { y << YAML::Key << key << YAML::Value << value; };
    // First, what every output records, under the same names: its first line says whose it is.
    Provenance::of(info).visit(entry, entry);
    entry("status", status);
    if (!error.empty()) entry(status == "interrupted" ? "interrupted_by" : "error", error);
    // What only the record holds: where to read the scene again (run --resume), and which
    // library file each plugin was, with its checksum.
    entry("scene_path", info.scene_file.string());
    y << YAML::Key << "plugin_files" << YAML::Value << YAML::BeginSeq;
    for (const auto& p : info.plugins)
        y << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << p.name << YAML::Key << "file"
          << YAML::Value << p.file.string() << YAML::Key << "fnv1a_64" << YAML::Value << p.fingerprint << YAML::EndMap;
    y << YAML::EndSeq;
    y << YAML::Key << "command_line" << YAML::Value << YAML::Flow << command_line;
    y << YAML::Key << "overrides" << YAML::Value << YAML::Flow << overrides;
    if (resumed_from_step >= 0) entry("resumed_from_step", resumed_from_step);
    entry("steps", summary.steps);
    entry("evaluations", summary.evaluations);
    entry("simulated_time", summary.simulated_time);
    entry("loading_start", info.loading_start);
    entry("wall_seconds", summary.wall_seconds);
    entry("cpu_seconds", summary.cpu_seconds);
    entry("threads", worker_threads());  // what the times were taken with; the results do not depend on it
    if (!summary.stages_ended_early.empty())
        y << YAML::Key << "stages_ended_early" << YAML::Value << summary.stages_ended_early;
    if (!summary.integrator_statistics.empty()) {
        y << YAML::Key << "integrator_statistics" << YAML::Value << YAML::BeginMap;
        for (const auto& [name, value] : summary.integrator_statistics) entry(name, value);
        y << YAML::EndMap;
    }
    // What components chose for keys the scene left `auto` (the scene below keeps `auto`).
    if (!info.resolved_choices.empty()) {
        y << YAML::Key << "resolved_choices" << YAML::Value << YAML::BeginMap;
        for (const auto& c : info.resolved_choices)
            y << YAML::Key << c.key_path << YAML::Value << YAML::BeginMap << YAML::Key << "value" << YAML::Value
              << c.value << YAML::Key << "reason" << YAML::Value << c.reason << YAML::EndMap;
        y << YAML::EndMap;
    }
    // What the integrator's step misses (the run warned of each as it began).
    if (!info.caveats.empty()) y << YAML::Key << "caveats" << YAML::Value << info.caveats;
    y << YAML::Key << "scene" << YAML::Value << YAML::Load(info.resolved_scene);
    y << YAML::EndMap;
    return std::string(y.c_str()) + "\n";
}

std::optional<RecordedRun> read_recorded_run(const std::filesystem::path& dir) {
    const auto file = dir / "run.yaml";
    if (std::error_code ec; !std::filesystem::exists(std::filesystem::symlink_status(file, ec))) return std::nullopt;
    const auto read = read_run_record(dir);
    if (!read.text) throw InputError(fmt::format("cannot read '{}': {}", file.string(), read.problem));
    YAML::Node record;
    try {
        record = YAML::Load(*read.text);
    } catch (const YAML::Exception&) {
        return std::nullopt;
    }
    if (!record.IsMap() || !record["framework"] || record["framework"].as<std::string>("") != "frictionlab")
        return std::nullopt;
    RecordedRun run;
    run.scene_file = record["scene_path"].as<std::string>("");
    if (const auto overrides = record["overrides"]; overrides && overrides.IsSequence())
        for (const auto& o : overrides) run.overrides.push_back(o.as<std::string>(""));
    run.status = record["status"].as<std::string>("");
    if (run.status == "completed") run.status = "done";  // a record written before a finished run was `done`
    run.scene_hash = record["scene_hash"].as<std::string>("");
    run.summary.steps = record["steps"].as<long long>(0);
    run.summary.evaluations = record["evaluations"].as<long long>(0);
    run.summary.simulated_time = record["simulated_time"].as<double>(0);
    run.summary.wall_seconds = record["wall_seconds"].as<double>(0);
    run.summary.cpu_seconds = record["cpu_seconds"].as<double>(0);
    run.loading_start = record["loading_start"].as<double>(0);
    for (const char* name : checkpoint_files)
        run.has_checkpoint = run.has_checkpoint || std::filesystem::exists(dir / name);
    return run;
}

}  // namespace frictionlab
