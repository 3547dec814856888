#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/model/junction_counts.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/model/normal_force_drift.hpp"
#include "frictionlab/base/param_spec.hpp"

namespace frictionlab {

/// Two-state (pinned, slipping) junction friction: K. Thøgersen, J. K. Trømborg, H. A. Sveinsson,
/// A. Malthe-Sørenssen, J. Scheibert, Phys. Rev. E 89, 052401 (2014), doi:10.1103/PhysRevE.89.052401;
/// J. K. Trømborg, H. A. Sveinsson, J. Scheibert, K. Thøgersen, D. S. Amundsen,
/// A. Malthe-Sørenssen, PNAS 111, 8764 (2014), doi:10.1073/pnas.1321752111 (theory.md D.2.2).
///
/// Every interface block i carries a fixed number N_s of junctions. A junction force f > 0 resists
/// motion in +x; the block feels -sum_j f_j. With f_N,i the block's normal force ("normal_force"):
///
///     pinned     f_ij = k_i (x_i - x_ij0)
///     slipping   f_ij = s_ij f_d,        f_d = mu_d f_N,i / N_s,   s_ij = sign of f_ij at breaking
///     breaking   pinned -> slipping when |f_ij| > f_s = mu_s f_N,i / N_s (strict); draw t_R
///     re-pinning slipping -> pinned, unloaded at the current position, when t >= breaking time + t_R
///     t_R        Gaussian (slipping_time_mean, slipping_time_sd) truncated to t > 0 by rejection,
///                keyed on (seed, block, junction index, sliding_time, the junction's draw count)
///     k_i        = k_bar sqrt(f_N,i / <f_N>),  <f_N> = mean of f_N over the interface, now
///
/// Stiffness: k_i follows the current normal force, re-evaluated at every commit (and at the start of
/// each stage) together with f_s and f_d, and frozen within a step (theory.md B.17). <f_N> is the
/// current interface mean, so k_bar is the stiffness of a block at the mean load and a uniform load
/// gives k_i = k_bar for any F_N. A stiffness change changes the slope of a pinned junction, not its
/// force: the junction keeps the force it carries at the commit (a contact stiffening under load does
/// not jump in stored force). Before any normal force exists (<f_N> = 0) k_i = k_bar and f_s = f_d = 0.
///
/// Pinned forces enter the block force through aggregates, so a commit in the stuck phase is O(1) per
/// block: f_ij = b_j + c_i + k_i (x_i - x_c,i), where b_j is fixed while the junction stays pinned and
/// the block scalars c_i, x_c,i absorb the increments of every commit (c += k (x - x_c), x_c = x); the
/// breaking test needs only max_j b_j and min_j b_j. Whenever the pinned set changes, c is folded back
/// into the b_j, so round-off never accumulates.
///
/// Step structure (B.17): states, stiffness and thresholds are frozen within a step; commit() applies,
/// per block: the new k_i, f_s, f_d from the end-of-step normal force (the base contact writes it in
/// its own, earlier, commit), re-pinning of expired junctions, then breaking. While a stage has
/// friction_events false (settling, B.18) nothing re-pins or breaks; junctions pinned beyond f_s when
/// events are switched on break at the first commit of that stage.
///
/// Stored energy (potential_energy): sum over pinned junctions of f_ij^2 / (2 k_i); slipping ones carry a
/// constant force and store nothing. Breaking, re-pinning unloaded and stiffness changes move it
/// without work (dissipation by definition).
class TwoStateJunctions final : public FrictionLaw {
public:
    bool checkpointable() const override { return true; }
    void save_state(StateOut& out) const override { out(*this); }
    void restore_state(StateIn& in) override { in(*this); }
    template <class Archive>
    void serialize(Archive& ar) {
        ar(blocks_, events_, next_event_, drift_);
    }
    struct Params {
        int junctions_per_block = 100;
        double mu_s = 0.4;
        double mu_d = 0.17;
        double junction_stiffness = 2.8e4;
        double slipping_time_mean = 2e-4;
        double slipping_time_sd = 6e-5;
        std::string node_set = "interface";
    };

    static constexpr std::string_view type = "two_state_junctions";
    static ParamSpec<Params> spec();

    TwoStateJunctions(const Params&, const Context&);

    std::string describe() const override;
    void add_forces(const StageView& s, ForceView& f) override;
    void begin_stage(const StageInfo&, const StageView&) override;
    void commit(const StageView& end, double dt) override;
    double next_event_time() const override { return next_event_; }
    double potential_energy(const StageView& s) const override;
    /// Quasi-static regime: always. Within a step a pinned junction is linear in its block's position
    /// (k_i, frozen) and a slipping one carries the constant s f_d. Its stiffness is N_p k_i on the
    /// block's x; its foreseen event the first pinned junction reaching f_s at the blocks' velocities,
    /// or f_N moving enough to matter to k_i and f_s (NormalForceDrift; none while friction events are
    /// off); the re-pinnings are scheduled (next_event_time).
    bool quasi_static_regime(const StageView&) const override { return true; }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const override;
    double foreseen_event_time(const StageView& s) const override;

    Index blocks() const { return static_cast<Index>(blocks_.size()); }
    Index junctions_per_block() const { return n_s_; }
    Index pinned(Index i) const { return block(i).pinned; }
    Index slipping(Index i) const { return n_s_ - block(i).pinned; }
    /// Re-pinning time of a slipping junction (infinity while pinned), s.
    double repin_time(Index i, Index j) const { return block(i).deadline[static_cast<std::size_t>(j)]; }
    /// k_i, f_s and f_d of block i as frozen for the current step.
    double stiffness(Index i) const { return block(i).k; }
    double breaking_force(Index i) const { return block(i).f_s; }
    double slipping_force(Index i) const { return block(i).f_d; }
    /// Force of junction j of block i at block position x (> 0 resists motion in +x), junction by junction.
    double junction_force(Index i, Index j, double x) const;
    /// Sum of the junction forces of block i at block position x, from the aggregates.
    double block_force(Index i, double x) const;

private:
    struct Block {
        // Per junction: pinned load b_j (force b_j + c + k (x - x_c)), slipping sign s_j, re-pinning
        // time, draw counter, state.
        std::vector<double> load, sign, deadline;
        std::vector<std::uint64_t> draws;
        std::vector<std::uint8_t> slipping;
        Index pinned = 0;
        double load_sum = 0, load_max = 0, load_min = 0, sign_sum = 0;
        double next_deadline;
        double k, f_s = 0, f_d = 0, c = 0, x_c;
        template <class Archive>
        void serialize(Archive& ar) {
            ar(load, sign, deadline, draws, slipping, pinned, load_sum, load_max, load_min, sign_sum, next_deadline, k,
               f_s, f_d, c, x_c);
        }
    };

    const Block& block(Index i) const { return blocks_[static_cast<std::size_t>(i)]; }
    void follow_normal_force(Index i, double x, double mean_normal_force);
    bool repin_expired(Block& b, double t) const;
    bool break_overloaded(Block& b, Index i, double t) const;
    static void refresh_aggregates(Block& b);
    /// The mean normal force over the blocks, and the characteristic slip it sets, published.
    double follow_mean_normal_force();

    std::string name_;
    Index n_s_;
    double mu_s_, mu_d_, k_bar_;
    std::uint64_t seed_;
    double slipping_time_mean_, slipping_time_sd_;  // Gaussian t_s, truncated to t > 0 (random.hpp)
    NodeSet nodes_;
    std::vector<Block> blocks_;
    const Eigen::ArrayXd* normal_force_;
    NormalForceDrift drift_;  // k and f_s follow f_N at commits: a quiet span ends before they drift
    Eigen::ArrayXd* friction_force_;
    JunctionCounts::Writable counts_;
    double* characteristic_slip_ = nullptr;  // published; follows the mean normal force
    bool events_ = true;
    double next_event_;
};

}  // namespace frictionlab
