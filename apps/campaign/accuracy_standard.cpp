#include "frictionlab/campaign/accuracy_standard.hpp"

#include <algorithm>
#include <cmath>

namespace frictionlab {

std::string to_string(Verdict v) {
    switch (v) {
        case Verdict::pass:
            return "pass";
        case Verdict::fail:
            return "fail";
        case Verdict::not_judged:
            break;
    }
    return "not judged";
}

Verdict EnsembleJudgement::verdict() const {
    bool judged = false;
    for (const auto& s : statistics) {
        if (s.verdict == Verdict::fail) return Verdict::fail;
        judged = judged || s.verdict == Verdict::pass;
    }
    return judged ? Verdict::pass : Verdict::not_judged;
}

double accuracy_level() { return two_sided_p(2.0); }

std::vector<double> column(const std::vector<EventStatistics>& runs, std::size_t index) {
    std::vector<double> out;
    out.reserve(runs.size());
    for (const auto& r : runs) out.push_back(r.values.at(index));
    return out;
}

EnsembleJudgement judge_ensemble(const std::vector<EventStatistics>& runs,
                                 const std::vector<EventStatistics>& reference,
                                 const std::vector<EventStatistics>* half_step, std::uint64_t seed) {
    EnsembleJudgement out;
    const std::size_t count = event_statistics().size();
    out.statistics.resize(count);
    std::vector<double> p_beyond_spread(count, EnsembleSummary::nan);  // Holm's family
    for (std::size_t i = 0; i < count; ++i) {
        StatisticJudgement& s = out.statistics[i];
        const auto values = column(runs, i), reference_values = column(reference, i);
        s.summary = summarize(values);
        const EnsembleSummary r = summarize(reference_values);
        if (half_step) {
            const EnsembleSummary h = summarize(column(*half_step, i));
            s.halving_spread = std::abs(h.mean - r.mean);
        }
        if (s.summary.n < 2 || r.n < 2) continue;
        s.difference = difference_of_means(values, reference_values, seed + i);
        const double d = std::abs(s.difference.value), se = s.difference.standard_error;
        s.tolerance = std::max(2 * se, std::isnan(s.halving_spread) ? 0.0 : s.halving_spread);
        s.p = se > 0 ? two_sided_p(d / se) : (d > 0 ? 0.0 : 1.0);
        if (d <= s.halving_spread) {
            s.verdict = Verdict::pass;  // within the reference's own step-halving spread
            continue;
        }
        p_beyond_spread[i] = s.p;
    }
    const std::vector<bool> rejected = holm_rejections(p_beyond_spread, accuracy_level());
    for (std::size_t i = 0; i < count; ++i)
        if (!std::isnan(p_beyond_spread[i])) out.statistics[i].verdict = rejected[i] ? Verdict::fail : Verdict::pass;
    return out;
}

}  // namespace frictionlab
