#include "frictionlab/campaign/study_run.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/interrupt_signals.hpp"
#include "frictionlab/campaign/case_outputs.hpp"

namespace frictionlab {

namespace {

double load_start(const Scene& scene) {
    double t = 0;
    for (std::size_t i = 0; i + 1 < scene.stages.size(); ++i) t += scene.stages[i].duration;
    return t;
}

}  // namespace

StudyResult run_study(const Study& study, const std::vector<CampaignRun>& runs, const std::filesystem::path& output,
                      const Registry& registry, spdlog::logger& log, CampaignOptions options) {
    options.reuse_finished = false;
    prepare_campaign_directory(study, output, options);
    StudyResult result;
    result.seed = runs.front().scene.seed;
    for (const auto& [key, value] : runs.front().values) result.knob_columns.push_back(key);
    const auto records = run_campaign(runs, output, registry, log, options);
    if (options.stop_signal && *options.stop_signal != 0)
        throw Interrupted(fmt::format("interrupted by {}: the study's cases stopped; run it again to start afresh",
                                      InterruptSignals::name(*options.stop_signal)),
                          *options.stop_signal);
    // Each run is compared with the reference's run of its seed: those come first, one per seed.
    const std::size_t seeds = std::max<std::size_t>(1, study.seeds.size());
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const CampaignRun& run = runs[k];
        const Scene& scene = run.scene;
        const bool reference = run.case_index == 0;
        StudyRow row;
        row.name = study.cases.at(run.case_index).name;
        row.label = study.label(run);
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
        row.outcome =
            read_case_outcome(scene.output_directory, *files, scene.stages.front().duration, load_start(scene));
        row.errors = compare(reference ? row.outcome : result.rows.at(k % seeds).outcome, row.outcome);
        log.info("study case {}: {:.3g} s wall ({:.3g} s CPU), {} steps, {} evaluations", row.label,
                 row.summary.wall_seconds, row.summary.cpu_seconds, row.summary.steps, row.summary.evaluations);
        result.rows.push_back(std::move(row));
    }
    return result;
}

}  // namespace frictionlab
