#pragma once
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/output/table_writer.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/model/junction_counts.hpp"
#include "frictionlab/simulation/run.hpp"

namespace frictionlab {

/// Local dynamics of chosen interface blocks and the real contact of the whole interface: the
/// four phases of Li et al. (2020) §3.3, Fig. 9 (detachment, fast slip, slow slip, rejuvenation;
/// Ben-David, Cohen & Fineberg, Science 330, 211 (2010), doi:10.1126/science.1194777).
///
/// Per chosen block i (0-based along "interface"; the paper's block 6 is 5), one row per observation
/// in <prefix>_block_<i>.csv:
///
///     normalised pinned count  Ñ_p = N_p(i,t) / N_p(i,0)                      (Eq. 17)
///         N_p(i,0) is the pinned count just before the block's first junction breaks in an event
///         (B.20). Taken as N_p at the last observation at which every junction of the block was
///         pinned (N_s = N_d = 0), so it is renewed before each event; NaN until there was one.
///     fractions                N_p/N, N_s/N, N_d/N with N = N_p + N_s + N_d (NaN when N = 0)
///     slip                     u(i,t) = x(i,t) - x0(i), absolute positions (B.20), and the slip
///                              since the first observation of stage `loading_stage`
///     velocity                 vx of the block
///     friction, normal force   the published fields friction_force and normal_force (NaN if absent)
///     bond forces (Fig. 9d)    x-force on the block from the straight interface spring to its left
///                              and right neighbour: F = K (r - r0) Δx / r, Δx = x_neighbour - x_i,
///                              r the current and r0 the reference length, K = Body::bond_stiffness.
///                              The straight interface bond only: diagonal springs and bond damping
///                              are not included. NaN at the interface's ends, where no such spring
///                              is in Body::bonds, or when the bulk model states no stiffness.
///
/// On a 2D interface (a 3D body) block i is the i-th of the interface set (interface_history's
/// column block_<i>), and its bond forces are NaN: Body::bond_stiffness is then the 2D lattice's K,
/// which a layer's straight bond and its diagonals across give together, not one spring's.
///
/// Whole interface, <prefix>.csv: total junction count N = Σ_i (N_p + N_s + N_d), the pinned, sliding
/// and dislocated totals and the pinned fraction. The real contact area A = N π r̄² (Li2020 §2.2) is a
/// column only when an effect publishes the scalar junction_area (π r̄², m²): the observer does not
/// know r̄ otherwise, and N is proportional to A. With `map`, <prefix>_map.csv holds every block's A
/// at every observation: the contact map the experiments image (Rubinstein et al. 2004).
///
/// Reads the junction counts (required: a friction law with junctions), positions and velocities;
/// nothing runs between observations.
class ContactArea final : public Observer {
public:
    // Checkpoints: what changes as it observes (its tables are cut back and appended to by the run).
    bool checkpointable() const override { return params_.format == TableFormat::csv; }
    void save_state(StateOut& out) const override { out(*this); }
    void restore_state(StateIn& in) override { in(*this); }
    template <class Archive>
    void serialize(Archive& ar) {
        ar(fixed_length(blocks_), last_step_);
    }
    struct Params {
        std::vector<double> blocks{5};  // whole numbers; real_list is the scene's list type
        std::string prefix = "contact_area";
        std::string loading_stage = "load";
        bool map = false;
        TableFormat format = TableFormat::csv;
    };
    static constexpr std::string_view type = "contact_area";
    static ParamSpec<Params> spec();

    ContactArea(const Params& p, const Context& ctx);
    void begin(const RunView& view) override;
    void observe(const RunView& view) override;

    /// x-force (N) on node `i` from a straight spring of stiffness k to node `j` whose reference
    /// length is r0: k (r - r0) (x_j - x_i) / r.
    static double bond_force_x(double k, double r0, double xi, double zi, double xj, double zj);

private:
    /// A straight interface spring from a block to one neighbour.
    struct Bond {
        Index neighbour = -1;  // node; -1: none
        double rest_length = 0;
    };
    struct Block {
        Index index = 0;  // along the interface
        Index node = 0;
        Bond left, right;
        double pinned_reference = std::numeric_limits<double>::quiet_NaN();
        double x_at_loading = std::numeric_limits<double>::quiet_NaN();
        std::unique_ptr<TableWriter> table;
        template <class Archive>
        void serialize(Archive& ar) {
            ar(pinned_reference, x_at_loading);
        }
    };

    Bond bond_between(const Body& body, Index node, Index neighbour) const;
    double bond_force(const RunView& view, const Block& b, const Bond& bond) const;

    Params params_;
    std::vector<Index> interface_;
    std::vector<Block> blocks_;
    JunctionCounts counts_;
    const Eigen::ArrayXd* friction_ = nullptr;
    const Eigen::ArrayXd* normal_ = nullptr;
    const double* junction_area_ = nullptr;
    double stiffness_ = 0;
    long long last_step_ = -1;
    std::unique_ptr<TableWriter> interface_table_, map_table_;
    std::vector<double> row_;
};

}  // namespace frictionlab
