#pragma once
// The collected results of a sweep, read back from each run's outputs (the files its observers
// name, case_outputs.hpp): sweep.csv, one row per run, and events.csv, one row per rupture event
// of every run. Each is a campaign table (campaign_table.hpp); their columns are in
// share/docs/scene-format.md ("Sweeps").
#include <filesystem>
#include <vector>

#include "frictionlab/campaign/campaign.hpp"
#include "frictionlab/campaign/case_record.hpp"
#include "frictionlab/campaign/sweep.hpp"

namespace frictionlab {

class Registry;

/// `registry` gives the units of the varied keys (key_unit.hpp).
void write_sweep_tables(const Sweep& sweep, const std::vector<CampaignRun>& runs,
                        const std::vector<CaseRecord>& records, const Registry& registry,
                        const std::filesystem::path& output);

}  // namespace frictionlab
