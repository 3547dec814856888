#pragma once
// A table a campaign writes (sweep.csv, events.csv, sweep_statistics.csv): one header line and its
// rows, so that pandas.read_csv, numpy.genfromtxt(names=True) and spreadsheets read it as is; what
// wrote it (version, campaign file and title, seeds) and each column's unit go to its sidecar
// NAME.csv.meta.yaml, as a run's tables have theirs (output/provenance.hpp).
#include <filesystem>
#include <string>
#include <vector>

#include "frictionlab/campaign/campaign.hpp"

namespace frictionlab {

struct CampaignColumn {
    std::string name;
    std::string unit;  // SI, "1" for a pure number, empty for text, or unit_of_row
};

/// What sets the runs apart (the varied key paths, then `seed`), in order of first use, each with
/// its unit as the key's declaration gives it (key_unit.hpp).
std::vector<CampaignColumn> value_columns(const std::vector<CampaignRun>& runs, const Registry& registry);

/// The keys a campaign's cases set, told apart: those that take more than one value over its runs
/// are its axes (a column each); one set to the same value in every run (an output cadence, a
/// duration) is a constant of the campaign, recorded once in the sidecars.
struct CampaignKeys {
    std::vector<CampaignColumn> varied;
    CampaignValues constants;  // key, the value every run has
};
CampaignKeys split_varied(const std::vector<CampaignColumn>& columns, const std::vector<CampaignRun>& runs);

/// The unit of a column whose rows each name their unit in the column `unit` (a statistic's mean).
inline constexpr const char* unit_of_row = "(unit column)";

/// The columns that summarize an event statistic over an ensemble, as a sweep's
/// sweep_statistics.csv and a study's ensemble.csv give them: statistic, unit, n, missing, mean,
/// sd, ci_low, ci_high and `interval`, empty where the bounds are given, else why not
/// (ensemble_statistics.hpp).
std::vector<CampaignColumn> statistic_summary_columns();

/// Writes `rows` (CSV lines, each ending in a newline) under the header of `columns` into `file`,
/// and its sidecar, each atomically. `kind` names the campaign file's key in the sidecar
/// (`sweep` -> `sweep_file`); `note` says where more is recorded; `keys`, if given, are recorded as
/// `varied` (the columns that are axes) and `constants` (key: value).
void write_campaign_table(const Campaign& campaign, const std::string& kind, const std::filesystem::path& file,
                          const std::vector<CampaignColumn>& columns, const std::string& rows, const std::string& note,
                          const CampaignKeys* keys = nullptr);

}  // namespace frictionlab
