#pragma once
// The errors of an accuracy study, computed from the outputs each case wrote (the precursors and
// interface_history observers the study adds): what a user would compare by hand, so every number
// can be checked against the case's files. Profiles of runs at different lattice resolutions are
// compared on x/L, the case's profile linearly interpolated at the reference's blocks.
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "frictionlab/campaign/case_outputs.hpp"

namespace frictionlab {

/// What one case's outputs say about the quantities a study compares.
struct CaseOutcome {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> x_over_length;  // of each interface block, ordered along x
    /// Normal and friction force of each block at the end of the settling stage, over the mean
    /// normal force per block (so that profiles at different resolutions compare).
    std::vector<double> settled_normal, settled_friction;
    double first_precursor_time_since_loading = nan;  // start of the first non-global event (s)
    double first_precursor_force = nan;               // F_S at its start (N)
    double global_slip_force_ratio = nan;             // F_S/F_N at the first global slip (theory.md B.20)
    std::vector<double> event_slip;                   // slip of each block over the first event (m)
    /// The rupture events up to and including the second global slip, in time order: start since
    /// loading began (s), F_S at it (N) and length l/L.
    struct Event {
        double time, force, length;
    };
    std::vector<Event> events;
    bool any_event = false, global_slip = false;
};

/// Reads a case's output directory: the interface profiles there and the rupture events and
/// summary in `rupture` (case_outputs.hpp). `settle_end` is the end of the settling stage and
/// `load_start` the start of the loading stage (s).
CaseOutcome read_case_outcome(const std::filesystem::path& dir, const RuptureFiles& rupture, double settle_end,
                              double load_start);

/// Relative errors of a case against the reference: |a - r| / |r| for numbers, relative L2 on x/L
/// for profiles. NaN where the case lacks what the reference has (named in `note`).
struct CaseErrors {
    double settled_normal_force = CaseOutcome::nan, settled_friction_force = CaseOutcome::nan;
    double first_precursor_time_since_loading = CaseOutcome::nan, first_precursor_force = CaseOutcome::nan;
    double global_slip_force_ratio = CaseOutcome::nan, event_slip = CaseOutcome::nan;
    /// Over the events both have (in time order, up to the second global slip): the largest
    /// relative error of their start time and F_S, and the largest difference of l/L.
    double event_time = CaseOutcome::nan, event_force = CaseOutcome::nan, event_length = CaseOutcome::nan;
    std::string note;
};

CaseErrors compare(const CaseOutcome& reference, const CaseOutcome& outcome);

/// ||f(x_ref) - f_ref|| / ||f_ref|| over the reference points, f linearly interpolated from (x, values)
/// (x increasing); exactly 0 when the grids and values are equal. NaN if either is empty.
double relative_l2_on_grid(const std::vector<double>& x_ref, const std::vector<double>& reference,
                           const std::vector<double>& x, const std::vector<double>& values);

}  // namespace frictionlab
