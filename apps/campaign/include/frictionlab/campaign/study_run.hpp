#pragma once
// Runs an accuracy study (study.hpp): every run, the reference's first, each an ordinary run into
// its directory below <output>/cases, then the errors of each run against the reference's run of
// the same seed (study_metrics.hpp). One run at a time (the default) keeps the wall times
// comparable; each run is bit-reproducible however many run at once.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <spdlog/logger.h>

#include "frictionlab/campaign/runner.hpp"
#include "frictionlab/campaign/study.hpp"
#include "frictionlab/campaign/accuracy_standard.hpp"
#include "frictionlab/campaign/event_statistics.hpp"
#include "frictionlab/campaign/study_metrics.hpp"

namespace frictionlab {

struct StudyRow {
    std::string name, family;
    std::string label;               // the name, with the seed where the study has seeds
    std::string run;                 // its directory below cases/: <name>, or <name>/seed_<seed>
    std::string scene_hash;          // of the run's resolved scene (seed included), as its run.yaml records it
    std::vector<std::string> knobs;  // one value per StudyResult::knob_columns ("" where it does not apply)
    RunSummary summary;
    CaseOutcome outcome;
    CaseErrors errors;
};

/// One case's runs over seeds as an ensemble (accuracy_standard.hpp): the first over the study's seeds,
/// a second over as many other seeds for a case that failed a statistic on the first (it is rejected
/// only for a statistic that fails on both).
struct StudyEnsemble {
    std::size_t case_index = 0;
    std::string name, family;
    int ensemble = 1;  // 1: the study's seeds; 2: the retest's
    std::vector<EventStatistics> runs;
    EnsembleJudgement judgement;  // against the reference's ensemble of the same seeds; none for it
    double cpu_seconds = 0;       // mean of its runs'
};

struct StudyResult {
    /// integrator.type, then every key path the study's overrides set, in order of first use.
    std::vector<std::string> knob_columns;
    std::vector<StudyRow> rows;            // one per run, the reference's first
    std::vector<StudyEnsemble> ensembles;  // with two seeds or more: every case's, the reference's first
    std::uint64_t seed = 0;                // the base scene's (a case may set its own)
};

/// The study's output directory is created (replaced with `options.overwrite`); in an existing one
/// of FrictionLab's, runs recorded finished with the same scene are reused with their recorded
/// times (`options.reuse_finished`), so a stopped study goes on. A run that
/// fails is a row of NaN errors with the reason in its note; a failing reference throws RunError,
/// a stop signal Interrupted.
StudyResult run_study(const Study& study, const std::vector<CampaignRun>& runs, const std::filesystem::path& output,
                      const Registry& registry, spdlog::logger& log, const CampaignOptions& options);

/// With two seeds or more (Study::ensembles): each case's runs as an ensemble judged against the
/// reference's (accuracy_standard.hpp), a failing case run again on other seeds, into `result`.
void judge_ensembles(const Study& study, const std::vector<CampaignRun>& runs, const std::vector<CaseRecord>& records,
                     const std::filesystem::path& output, const Registry& registry, spdlog::logger& log,
                     const CampaignOptions& options, StudyResult& result);

}  // namespace frictionlab
