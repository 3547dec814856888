#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/model/junction_counts.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/output/table_writer.hpp"
#include "frictionlab/simulation/run.hpp"
#include "contact_changes.hpp"
#include "event_check.hpp"
#include "interface_geometry.hpp"
#include "loading_drops.hpp"
#include "rupture_criterion.hpp"
#include "rupture_event_detector.hpp"

namespace frictionlab {

/// Rupture events along the interface: the precursors of Li et al. (2020) Figs. 6-8 and the global
/// slips, defined from the scene's own scales so that the definition carries over to another drive,
/// friction law or lattice (theory.md §5a). Li, Zhao, Xiong & Liu, Acta Mech. Sin. 36 (2020),
/// doi:10.1007/s10409-020-00955-2, §3.1-3.2; Rubinstein, Cohen & Fineberg, PRL 98, 226103 (2007),
/// doi:10.1103/PhysRevLett.98.226103; Ben-David, Rubinstein & Fineberg, Nature 463, 76 (2010).
///
/// At each observation (cadence ≤ 10 µs) an interface block is rupturing when both hold:
///
///     its contact is broken   criterion pinned_fraction: (N_s + N_d) > ruptured_fraction N (the
///                             real-contact-area drop of the experiments); slipping: the law's stuck
///                             spring is broken; slip_rate: no contact measure, rate alone
///     it slips fast           its mean slip rate over rate_window (auto: the slider's wave-crossing
///                             time L/c_S, over which its vibrations average out) exceeds quiet_speed
///                             (auto: half the drive's speed: slower, it creeps with the load)
///
/// A block out of contact (no junctions, or without junction counts no normal force) never ruptures;
/// its lift-off and re-contact are reported on their own. RuptureEventDetector joins rupturing blocks
/// into events, connected regions of the space-time map (neighbours within quiet_time, auto: two
/// wave-crossing times), and leaves out an event none of whose blocks slipped min_slip (auto: a tenth
/// of the law's characteristic slip, the slip a contact takes before it breaks). Every run then checks its events
/// (event_check.hpp): its global slips against the drops of its loading curve, its precursors against the slip field.
///
/// On a 3D body the interface is a grid (interface_geometry.hpp): events are connected regions in x, y
/// and time, measured across too (their tables then have the columns across, after the others).
///
/// Outputs, in the run's output directory (columns in share/docs/glossary.md):
///
///     precursors.csv             one row per event, written when the event ends; at the end of
///                                the run an open event is written with finished = 0
///     precursor_fronts.csv       per event and ruptured block: when it first ruptured (sampled
///                                every front_every while an event runs, so to that resolution)
///     contact_changes.csv        per block that lifts off or touches down again: when
///     precursors_summary.yaml    the settings the run used, precursors before the first global slip,
///                                the F_S/F_N at its start (B.20), the peak F_S, the number of
///                                events, the check of the events, run metadata; rewritten
///                                atomically after each event
///
/// With end_stage: after_global_slip, the stage ends once the first global slip is over: the detector
/// has reported it ended and, with the check on, the loading curve has risen again after its fall,
/// so that the event and its check are complete. An ensemble of the static coefficient and the
/// precursors before it need not load on.
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
        ar(as_built(detector_), slip_rate_, drops_, checked_, rupturing_, broke_at_, intact_at_, last_observed_,
           contact_changes_, stage_end_, stage_to_end_);
    }
    enum class Criterion { automatic, pinned_fraction, slipping, slip_rate };
    enum class EndStage { never, after_global_slip };
    static constexpr double auto_value = std::numeric_limits<double>::quiet_NaN();
    struct Params {
        Criterion criterion = Criterion::automatic;
        double ruptured_fraction = 0.5;
        double quiet_speed = auto_value;
        double rate_window = auto_value;
        double quiet_time = auto_value;
        double min_slip = auto_value;
        double front_every = 1e-6;
        double global_span = 0.95;
        double nucleation_load = 0.01;
        double drop_threshold = 0.03;
        double match_tolerance = 0.05;
        bool check = true;
        EndStage end_stage = EndStage::never;
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
    double finer_cadence() const override { return detector_ && detector_->open() ? params_.front_every : 0.0; }
    /// end_stage after_global_slip: the stage the first global slip ended in, once it is over.
    std::string stage_end(const StageInfo& stage) const override {
        return stage.index == stage_to_end_ ? stage_end_ : std::string();
    }

    /// The settings as resolved for this scene (every `auto` replaced by its value).
    const Params& settings() const { return params_; }

private:
    /// The blocks rupturing now, and which are in contact; `record`: at the observer's own cadence,
    /// whose observations the slip rate is measured against.
    void classify(const RunView& view, bool record);
    void observe_contact(const RunView& view);
    void report_ended(const RunView& view);
    void judge_stage_end(const RunView& view);
    void write(const RuptureEvent& e);
    EventCheck check() const;
    void write_summary(const RunView& view, bool run_ended) const;
    std::string summary_text(const RunView& view, const EventCheck& check, bool run_ended) const;

    Params params_;
    std::string stage_end_;              // why the stage ends (end_stage), once it must
    int stage_to_end_ = -1;              // the index of that stage
    bool min_slip_follows_law_ = false;  // min_slip auto while the law's scale is not yet known
    double characteristic_slip_ = std::numeric_limits<double>::quiet_NaN();
    double kinetic_coefficient_ = std::numeric_limits<double>::quiet_NaN();
    std::optional<RuptureEventDetector> detector_;
    SlipRate slip_rate_;
    LoadingDrops drops_;
    std::vector<CheckedEvent> checked_;
    std::optional<JunctionCounts> counts_;
    const Eigen::ArrayXd* slipping_ = nullptr;      // criterion slipping: the law's field
    const Eigen::ArrayXd* normal_force_ = nullptr;  // contact without junction counts; null: always in contact
    const double* law_slip_scale_ = nullptr;        // the law's published characteristic slip
    std::vector<Index> interface_;
    const double* driving_force_ = nullptr;
    const double* normal_load_ = nullptr;
    Eigen::ArrayXd slip_, rate_;
    RuptureMask rupturing_;
    BlockMask fast_;                       // slipping faster than quiet_speed
    Eigen::ArrayXd broke_at_, intact_at_;  // per block: when its contact broke, and the observation before
    double last_observed_ = std::numeric_limits<double>::quiet_NaN();
    BlockMask contact_;
    ContactChanges contact_changes_;
    std::unique_ptr<TableWriter> events_, fronts_, contact_table_;
    std::vector<double> row_;
};

}  // namespace frictionlab
