#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/output/table_writer.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/model/junction_counts.hpp"
#include "frictionlab/simulation/run.hpp"
#include "contact_changes.hpp"
#include "rupture_criterion.hpp"
#include "rupture_event_detector.hpp"

namespace frictionlab {

/// Rupture events along the interface: the precursors of Li et al. (2020) Figs. 6-8 and the first
/// global slip, detected as theory.md B.19 resolves the paper's undefined terms.
/// Li, Zhao, Xiong & Liu, "A 2D model for frictional sliding", 2020, §3.1-3.2; cf. Rubinstein,
/// Cohen & Fineberg, PRL 98, 226103 (2007), doi:10.1103/PhysRevLett.98.226103.
///
/// At each observation (cadence ≤ 10 µs, B.19) every interface block is judged ruptured or not:
///
///     pinned_fraction:  (N_s + N_d) > ruptured_fraction (N_p + N_s + N_d)
///     slip:             u = x - x0 grew by more than slip_threshold within quiet_time
///
/// A block out of contact (B.19b: no junctions, or without junction counts no normal force: it has
/// lifted off) is neither, takes no part in rupture decisions, and its lift-off and re-contact are
/// reported on their own.
///
/// and RuptureEventDetector groups the ruptured blocks into events (start, end, nucleation block,
/// extent l = min(L, x_max + l_s/2) with x_max the farthest ruptured block from the trailing edge,
/// global when the ruptured blocks span global_span of L, mean front speed, largest slip); an
/// event that ends within nucleation_window_quiet_times x quiet_time before a larger one starts
/// where it ruptured is that rupture's nucleation and is reported with it (B.19a). F_S and F_N are the published
/// scalars driving_force and normal_load at the event's start (NaN if the scene has none).
///
/// Outputs, in the run's output directory (columns in share/docs/glossary.md):
///
///     precursors.csv             one row per event, written when the event ends; at the end of
///                                the run an open event is written with finished = 0
///     precursor_fronts.csv       per event and ruptured block: when it first ruptured (sampled
///                                every front_every while the event runs, so to that resolution)
///     contact_changes.csv        per block that lifts off or touches down again: when
///     precursors_summary.yaml    precursors before the first global slip, the global static
///                                coefficient F_S/F_N at its start (B.20), the peak F_S, the number
///                                of events, run metadata; rewritten atomically after each event
///
/// Only observations during stages named `stage` count (empty: all), so the settling ramp, when
/// junctions are still being created, is not taken for a rupture.
class Precursors final : public Observer {
public:
    // Checkpoints: what changes as it observes (its tables are cut back and appended to by the run).
    bool checkpointable() const override { return params_.format == TableFormat::csv; }
    void save_state(StateOut& out) const override { out(*this); }
    void restore_state(StateIn& in) override { in(*this); }
    template <class Archive>
    void serialize(Archive& ar) {
        ar(as_built(detector_), as_built(slip_criterion_), ruptured_, contact_changes_);
    }
    enum class Criterion { automatic, pinned_fraction, slip };
    struct Params {
        Criterion criterion = Criterion::automatic;
        double ruptured_fraction = 0.5;
        double slip_threshold = 0.5e-6;
        double quiet_time = 2e-3;
        double front_every = 1e-6;
        double global_span = 0.95;
        double nucleation_window_quiet_times = 5;
        std::string stage = "load";
        std::string events_file = "precursors.csv";
        std::string fronts_file = "precursor_fronts.csv";
        std::string contact_file = "contact_changes.csv";
        std::string summary_file = "precursors_summary.yaml";
        TableFormat format = TableFormat::csv;
    };
    static constexpr std::string_view type = "precursors";
    static ParamSpec<Params> spec();

    Precursors(const Params& p, const Context& ctx);
    void begin(const RunView& view) override;
    void observe(const RunView& view) override;
    /// While an event runs: refines its blocks' first-rupture times, decides nothing else.
    void observe_between(const RunView& view) override;
    /// Junction counts (committed at each step) and positions only; contact by normal force, the
    /// one thing evaluated, only for a law without counts.
    bool between_reads_forces() const override { return counts_ == std::nullopt; }
    void resumed(const RunView& view) override { write_summary(view, false); }
    void end(const RunView& view) override;
    /// front_every while an event is open: its front's arrivals resolved to it.
    double finer_cadence() const override { return detector_ && detector_->open_event() ? params_.front_every : 0.0; }

    /// The summary file's text: what the detector found so far and the run's record.
    static std::string summary_text(const RuptureSummary& s, const ContactChanges& contact, const RunInfo& info,
                                    bool run_ended);

private:
    void write(const RuptureEvent& e);
    /// The blocks ruptured now (`rearm`: at the observer's own cadence, where the slip criterion
    /// may move its reference), and which are in contact.
    void classify(const RunView& view, bool rearm);
    void observe_contact(const RunView& view);
    void write_summary(const RunView& view, bool run_ended) const;

    Params params_;
    std::optional<RuptureEventDetector> detector_;
    std::optional<JunctionCounts> counts_;
    std::optional<SlipRuptureCriterion> slip_criterion_;
    const Eigen::ArrayXd* normal_force_ = nullptr;  // contact without junction counts; null: always in contact
    std::vector<Index> interface_;
    const double* driving_force_ = nullptr;
    const double* normal_load_ = nullptr;
    Eigen::ArrayXd slip_;
    RuptureMask ruptured_;
    BlockMask contact_;
    ContactChanges contact_changes_;
    std::unique_ptr<TableWriter> events_, fronts_, contact_table_;
    std::vector<double> row_;
};

}  // namespace frictionlab
