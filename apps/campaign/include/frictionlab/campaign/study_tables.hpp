#pragma once
// The tables of an accuracy study (study_run.hpp): study.csv for scripts, study.md for reading.
#include <filesystem>

#include "frictionlab/campaign/study.hpp"
#include "frictionlab/campaign/study_run.hpp"

namespace frictionlab {

/// study.csv: case, family, knobs, wall_seconds, cpu_seconds, steps, evaluations, the errors, note;
/// its sidecar as every campaign table's (campaign_table.hpp), the knobs' units from `runs`' scenes.
void write_study_csv(const StudyResult& result, const Study& study, const std::vector<CampaignRun>& runs,
                     const Registry& registry, const std::filesystem::path& file);
/// study.md: the same as a Markdown table, with the reference's values.
void write_study_markdown(const StudyResult& result, const Study& study, const std::filesystem::path& file);
/// ensemble.csv (with two seeds or more): per case, ensemble and event statistic, the ensemble's n,
/// mean, sd and interval, the difference to the reference with its interval and the verdict.
void write_ensemble_csv(const StudyResult& result, const Study& study, const std::filesystem::path& file);

}  // namespace frictionlab
