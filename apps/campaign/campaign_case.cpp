#include "frictionlab/campaign_case.hpp"

#include <fstream>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "frictionlab/output/json.hpp"

namespace frictionlab {

void write_case_record(const std::filesystem::path& dir, const CaseRecord& record) {
    const auto file = dir / case_record_file;
    const auto aside = dir / (std::string(case_record_file) + ".part");
    {
        std::ofstream out(aside, std::ios::trunc);
        // JSON strings are YAML strings: the reason may hold any character.
        out << fmt::format("status: {}\nreason: {}\nscene_hash: {}\nsteps: {}\nevaluations: {}\n"
                           "simulated_time: {:.17g}\nwall_seconds: {:.6g}\ncpu_seconds: {:.6g}\n",
                           record.status, json_quote(record.reason), json_quote(record.scene_hash),
                           record.summary.steps, record.summary.evaluations, record.summary.simulated_time,
                           record.summary.wall_seconds, record.summary.cpu_seconds);
        if (!out) return;
    }
    std::error_code ec;
    std::filesystem::rename(aside, file, ec);
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
