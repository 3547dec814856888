#include "frictionlab/campaign/case_record.hpp"

#include <yaml-cpp/yaml.h>

#include "frictionlab/output/atomic_file.hpp"

namespace frictionlab {

void write_case_record(const std::filesystem::path& dir, const CaseRecord& record) {
    YAML::Emitter y;
    y.SetDoublePrecision(17);
    y << YAML::BeginMap << YAML::Key << "status" << YAML::Value << record.status;
    y << YAML::Key << "reason" << YAML::Value << record.reason;
    y << YAML::Key << "scene_hash" << YAML::Value << record.scene_hash;
    y << YAML::Key << "steps" << YAML::Value << record.summary.steps;
    y << YAML::Key << "evaluations" << YAML::Value << record.summary.evaluations;
    y << YAML::Key << "simulated_time" << YAML::Value << record.summary.simulated_time;
    y << YAML::Key << "wall_seconds" << YAML::Value << record.summary.wall_seconds;
    y << YAML::Key << "cpu_seconds" << YAML::Value << record.summary.cpu_seconds << YAML::EndMap;
    write_file_atomically(dir / case_record_file, std::string(y.c_str()) + "\n");
}

CaseRecord read_case_record(const std::filesystem::path& dir) {
    CaseRecord record;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(dir / case_record_file, ec)) return record;
    try {
        const YAML::Node n = YAML::LoadFile((dir / case_record_file).string());
        record.status = n["status"].as<std::string>();
        record.reason = n["reason"].as<std::string>();
        record.scene_hash = n["scene_hash"].as<std::string>();
        record.summary.steps = n["steps"].as<long long>();
        record.summary.evaluations = n["evaluations"].as<long long>();
        record.summary.simulated_time = n["simulated_time"].as<double>();
        record.summary.wall_seconds = n["wall_seconds"].as<double>();
        record.summary.cpu_seconds = n["cpu_seconds"].as<double>();
    } catch (const YAML::Exception&) {
        return CaseRecord{};
    }
    return record;
}

}  // namespace frictionlab
