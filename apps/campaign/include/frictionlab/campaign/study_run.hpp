#pragma once
// Runs an accuracy study (study.hpp): the reference and every case one after another, each an
// ordinary run into <output>/cases/<name> (cases/<name>/seed_<seed> over seeds), then the errors
// of each case against the reference (study_metrics.hpp) into <output>/study.csv and
// <output>/study.md. One case at a time (the default) keeps the wall times comparable; each run is
// bit-reproducible however many run at once.
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <spdlog/logger.h>

#include "frictionlab/simulation/run.hpp"
#include "frictionlab/campaign/study.hpp"
#include "frictionlab/campaign/study_metrics.hpp"

namespace frictionlab {

struct StudyRow {
    std::string name, family;
    std::string label;               // the name, with the seed where the study has seeds
    std::string scene_hash;          // of the case's resolved scene (seed included), as its run.yaml records it
    std::vector<std::string> knobs;  // one value per StudyResult::knob_columns ("" where it does not apply)
    RunSummary summary;
    CaseOutcome outcome;
    CaseErrors errors;
};

struct StudyResult {
    /// integrator.type, then every key path the study's overrides set, in order of first use.
    std::vector<std::string> knob_columns;
    std::vector<StudyRow> rows;  // as Study::runs(): the reference's first
    std::uint64_t seed = 0;      // the base scene's (a case may set its own)
};

/// The study's output directory is created (replaced with `options.overwrite`); each case runs
/// into a new directory below it, above the estimated stable step with `options.allow_unstable_step`. A case that fails
/// is a row of NaN errors with the reason in its note; a failing reference throws RunError.
StudyResult run_study(const Study& study, const std::vector<Scene>& scenes, const std::filesystem::path& output,
                      const Registry& registry, spdlog::logger& log, const RunOptions& options, int jobs = 1);

/// study.csv: case, family, knobs, wall_seconds, cpu_seconds, steps, evaluations, the errors, note.
void write_study_csv(const StudyResult& result, const Study& study, const std::filesystem::path& file);
/// study.md: the same as a Markdown table, with the reference's values.
void write_study_markdown(const StudyResult& result, const Study& study, const std::filesystem::path& file);

}  // namespace frictionlab
