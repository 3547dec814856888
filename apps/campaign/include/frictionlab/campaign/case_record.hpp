#pragma once
// What became of one run of a campaign (campaign.hpp), run like `frictionlab run` into its scene's
// output directory below <campaign>/cases/. The record is written beside the run's outputs
// (case.yaml) so that a campaign run again into the same directory can tell a finished run (same
// scene hash, status done) from one that failed or was interrupted.
#include <filesystem>
#include <string>

#include "frictionlab/simulation/run.hpp"

namespace frictionlab {

struct CaseRecord {
    std::string status = "not run";  // "done", "failed", "interrupted" or "not run"
    std::string reason;              // why it failed or stopped
    std::string scene_hash;
    RunSummary summary;
    bool reused = false;  // finished by an earlier run of the campaign, not run again
};

/// The file below a case's output directory that records its outcome.
inline constexpr const char* case_record_file = "case.yaml";

/// Writes the record atomically (aside, then renamed): a campaign killed mid-write leaves none.
void write_case_record(const std::filesystem::path& dir, const CaseRecord& record);
/// The record of a case directory; status "not run" if it has none or it cannot be read.
CaseRecord read_case_record(const std::filesystem::path& dir);

}  // namespace frictionlab
