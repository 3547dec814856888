#include "frictionlab/campaign/study_run.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/interrupt_signals.hpp"
#include "frictionlab/campaign/case_outputs.hpp"

namespace frictionlab {

namespace {

/// Runs the study's `runs`; stops the study if asked to.
std::vector<CaseRecord> run_all(const std::vector<CampaignRun>& runs, const std::filesystem::path& output,
                                const Registry& registry, spdlog::logger& log, const CampaignOptions& options) {
    auto records = run_campaign(runs, output, registry, log, options);
    if (options.stop_signal && *options.stop_signal != 0)
        throw Interrupted(fmt::format("interrupted by {}: the study's cases stopped; run it again to start afresh",
                                      InterruptSignals::name(*options.stop_signal)),
                          *options.stop_signal);
    return records;
}

/// The runs of each case as ensembles, in the order of the study's cases (those without a run left
/// out); a run that failed is not a member.
std::vector<StudyEnsemble> ensembles_of(const Study& study, const std::vector<CampaignRun>& runs,
                                        const std::vector<CaseRecord>& records, int ensemble) {
    std::vector<StudyEnsemble> out;
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const CampaignRun& run = runs[k];
        if (out.empty() || out.back().case_index != run.case_index) {
            StudyEnsemble e;
            e.case_index = run.case_index;
            e.name = study.cases.at(run.case_index).name;
            const std::string& family = study.families.at(run.case_index);
            e.family = family.empty() ? run.values.front().second : family;
            e.ensemble = ensemble;
            out.push_back(std::move(e));
        }
        if (records[k].status != "done") continue;
        auto statistics = run_event_statistics(run.scene);
        if (!statistics) continue;
        StudyEnsemble& e = out.back();
        e.runs.push_back(std::move(*statistics));
        e.cpu_seconds += records[k].summary.cpu_seconds;
    }
    for (auto& e : out) e.cpu_seconds /= std::max<std::size_t>(1, e.runs.size());
    return out;
}

/// Each case's ensemble against the reference's (the first) and, if the study has one, the
/// half-step ensemble `half_step` of the same seeds.
void judge(std::vector<StudyEnsemble>& ensembles, const std::vector<EventStatistics>* half_step) {
    for (std::size_t i = 1; i < ensembles.size(); ++i)
        ensembles[i].judgement =
            judge_ensemble(ensembles[i].runs, ensembles.front().runs, half_step, 1000 * ensembles[i].case_index);
}

}  // namespace

StudyResult run_study(const Study& study, const std::vector<CampaignRun>& runs, const std::filesystem::path& output,
                      const Registry& registry, spdlog::logger& log, const CampaignOptions& options) {
    // Run again into the same directory, a study goes on: runs finished with the same scene keep
    // their results and their recorded times (an ensemble of RK4 references takes hours).
    prepare_campaign_directory(study, output, options);
    StudyResult result;
    result.seed = runs.front().scene.seed;
    for (const auto& [key, value] : runs.front().values) result.knob_columns.push_back(key);
    const auto records = run_all(runs, output, registry, log, options);
    // Each run is compared with the reference's run of its seed: those come first, one per seed.
    const std::size_t seeds = std::max<std::size_t>(1, study.seeds.size());
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const CampaignRun& run = runs[k];
        const Scene& scene = run.scene;
        const bool reference = run.case_index == 0;
        StudyRow row;
        row.name = study.cases.at(run.case_index).name;
        row.label = study.label(run);
        row.run = scene.output_directory.lexically_relative(output / "cases").generic_string();
        row.scene_hash = scene.hash;
        for (const auto& [key, value] : run.values) row.knobs.push_back(value);
        const std::string& family = study.families.at(run.case_index);
        row.family = family.empty() ? row.knobs.front() : family;
        row.summary = records[k].summary;
        const auto files = rupture_files(scene);
        if (records[k].status != "done" || !files) {
            const std::string reason = records[k].status != "done" ? records[k].reason : "no precursors observer";
            if (reference) throw RunError(fmt::format("the reference run {} failed: {}", row.label, reason));
            row.errors.note = fmt::format("run failed: {}", reason);
            result.rows.push_back(std::move(row));
            continue;
        }
        row.outcome = read_case_outcome(scene.output_directory, *files, scene.stages.front().duration,
                                        recorded_loading_start(scene.output_directory));
        row.errors = compare(reference ? row.outcome : result.rows.at(k % seeds).outcome, row.outcome);
        log.info("study case {}: {:.3g} s wall ({:.3g} s CPU), {} steps, {} evaluations", row.label,
                 row.summary.wall_seconds, row.summary.cpu_seconds, row.summary.steps, row.summary.evaluations);
        result.rows.push_back(std::move(row));
    }
    if (study.ensembles()) judge_ensembles(study, runs, records, output, registry, log, options, result);
    return result;
}

void judge_ensembles(const Study& study, const std::vector<CampaignRun>& runs, const std::vector<CaseRecord>& records,
                     const std::filesystem::path& output, const Registry& registry, spdlog::logger& log,
                     const CampaignOptions& options, StudyResult& result) {
    auto first = ensembles_of(study, runs, records, 1);
    const std::vector<EventStatistics>* half_step = study.half_step ? &first.at(1).runs : nullptr;
    judge(first, half_step);
    // A case that fails is run again, with the reference, on as many other seeds before it is rejected.
    std::vector<std::size_t> again{0};
    for (const auto& e : first)
        if (e.judgement.verdict() == Verdict::fail) again.push_back(e.case_index);
    result.ensembles = first;
    if (again.size() == 1) return;
    if (!study.run_failures_again) {
        log.warn(
            "study: {} case{} failed on the first {} seeds, not run again (run_failures_again: false): "
            "unconfirmed",
            again.size() - 1, again.size() == 2 ? "" : "s", study.seeds.size());
        return;
    }
    std::vector<std::int64_t> seeds;
    const std::int64_t after = *std::max_element(study.seeds.begin(), study.seeds.end());
    for (std::size_t k = 0; k < study.seeds.size(); ++k) seeds.push_back(after + 1 + static_cast<std::int64_t>(k));
    log.info("study: {} case{} failed on the first {} seeds; again on seeds {} to {}", again.size() - 1,
             again.size() == 2 ? "" : "s", study.seeds.size(), seeds.front(), seeds.back());
    Diagnostics diagnostics;
    const auto retest = study_runs(study, again, seeds, output, registry, diagnostics);
    if (!diagnostics.empty()) throw InputError(diagnostics.format());
    auto second = ensembles_of(study, retest, run_all(retest, output, registry, log, options), 2);
    judge(second, half_step);
    // Rejected only for a statistic that fails on both ensembles.
    for (auto& e : second)
        for (const auto& f : first)
            if (f.case_index == e.case_index && e.case_index != 0)
                for (std::size_t i = 0; i < e.judgement.statistics.size(); ++i)
                    if (f.judgement.statistics[i].verdict != Verdict::fail &&
                        e.judgement.statistics[i].verdict == Verdict::fail)
                        e.judgement.statistics[i].verdict = Verdict::pass;
    result.ensembles.insert(result.ensembles.end(), second.begin(), second.end());
}

}  // namespace frictionlab
