#pragma once
// The accuracy standard on ensembles (share/docs/accuracy-standard.md). Near threshold the slider is
// chaotic, so one seed is one draw of its events: a setting is judged on the ensemble of its runs
// over seeds against the reference's (RK4 at the paper's step) over the same seeds.
//
// Statistic by statistic (event_statistics.hpp), with d = mean(case) - mean(reference) and se the
// combined standard error sqrt(se_case^2 + se_reference^2), the setting passes when
//
//     |d| <= max(2 se, delta),   delta = |mean(reference at dt/2) - mean(reference)| where known,
//
// the reference's own spread under step halving. Many statistics are judged at once, so the
// two-standard-error test is corrected for their number by Holm's step-down (family-wise error
// 4.55 %, the two-sided level of 2 se, over the statistics of one case): a statistic within delta
// passes; of the others, those Holm rejects at that level fail. With one statistic this is the rule
// above exactly. A statistic with fewer than two values on either side is not judged.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "frictionlab/campaign/ensemble_statistics.hpp"
#include "frictionlab/campaign/event_statistics.hpp"

namespace frictionlab {

enum class Verdict { pass, fail, not_judged };
std::string to_string(Verdict v);

struct StatisticJudgement {
    EnsembleSummary summary;                       // of the case
    MeanDifference difference;                     // case - reference, with its bootstrap interval
    double halving_spread = EnsembleSummary::nan;  // delta; NaN without the half-step ensemble
    double tolerance = EnsembleSummary::nan;       // max(2 se, delta)
    double p = EnsembleSummary::nan;               // two-sided p of d / se, before Holm
    Verdict verdict = Verdict::not_judged;
};

struct EnsembleJudgement {
    std::vector<StatisticJudgement> statistics;  // in the order of event_statistics()
    /// Fails if any statistic fails.
    Verdict verdict() const;
};

/// The two-sided level of two standard errors, P(|Z| > 2) = 4.55 %: the family-wise error of Holm's test.
double accuracy_level();

/// Judges the runs of one case against the reference's runs (and, if given, the reference's at half
/// its step over the same seeds). `seed` keys the bootstrap.
EnsembleJudgement judge_ensemble(const std::vector<EventStatistics>& runs,
                                 const std::vector<EventStatistics>& reference,
                                 const std::vector<EventStatistics>* half_step, std::uint64_t seed);

/// The values of statistic `index` over `runs`.
std::vector<double> column(const std::vector<EventStatistics>& runs, std::size_t index);

}  // namespace frictionlab
