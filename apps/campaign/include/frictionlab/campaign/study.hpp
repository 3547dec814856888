#pragma once
// An accuracy study: a campaign (campaign.hpp) whose first case is a converged reference and whose
// other cases each turn accuracy knobs (integrator, time step or tolerance, lattice resolution,
// spring law, junction size), each case a list of `--set` overrides. Every run is observed as the
// metrics need (study_metrics.hpp) and compared with the reference's run of the same seed. The
// format is in share/docs/scene-format.md ("Accuracy studies"); study_run.hpp runs it. Reading is
// two-pass like a scene's: the study's own keys first, then every run's scene against the registry.
#include <filesystem>
#include <string>
#include <vector>

#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/campaign/campaign.hpp"

namespace frictionlab {

class Registry;

struct Study : Campaign {
    double observe_every = 1.0e-6;  // s, cadence of the rupture-event detection
    double profile_every = 1.0e-4;  // s, cadence of the interface profiles
    /// Of each case, the reference's first: the curve of the work-precision plot it belongs to
    /// (empty: its integrator type).
    std::vector<std::string> families;
    /// Whether case 1 is the reference at half its step (`half_step:`): over seeds, its difference
    /// from the reference is the reference's own spread (accuracy_standard.hpp).
    bool half_step = false;
    /// Whether a case that fails is run again on other seeds before it is rejected (`run_failures_again:`).
    bool run_failures_again = true;
    /// Whether the runs over the seeds are judged as ensembles (two seeds or more).
    bool ensembles() const { return seeds.size() >= 2; }

    /// The case's name, with the seed where the study has seeds: "hybrid (seed 2)".
    std::string label(const CampaignRun& run) const;
};

/// The study's own keys, with file:line:column errors; the base scene is not read yet. Its first
/// case is the reference, named "reference", then the reference at half its step, "half_step", if given.
Study read_study(const std::filesystem::path& file, Diagnostics& diagnostics);

/// Every run, the reference's first (one per seed): the base scene with the case's overrides and
/// the run's seed, checked like any scene (errors in an override point at the study file), writing
/// into `output`/cases/<name> (cases/<name>/seed_<seed> over seeds) and observed as the study needs
/// (its observers replace the scene's). Each run's values are the study's knobs: integrator.type,
/// the seed, then every key path the cases set, "" where a run's scene has no such key.
std::vector<CampaignRun> study_runs(const Study& study, const std::filesystem::path& output, const Registry& registry,
                                    Diagnostics& diagnostics);

/// The same for the given cases (indices into `cases`) with the given seeds only: an ensemble run
/// again on other seeds (accuracy_standard.hpp).
std::vector<CampaignRun> study_runs(const Study& study, const std::vector<std::size_t>& cases,
                                    const std::vector<std::int64_t>& seeds, const std::filesystem::path& output,
                                    const Registry& registry, Diagnostics& diagnostics);

}  // namespace frictionlab
