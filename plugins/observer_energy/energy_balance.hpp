#pragma once
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/output/csv_table.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/simulation/run.hpp"

namespace frictionlab {

/// The energies at the energy observer's first observation, which every later row is counted from.
/// At namespace scope: clang 14 cannot default-construct a nested class with member initializers
/// inside std::optional while its enclosing class is being defined (cereal's load of the optional).
struct EnergyReference {
    double kinetic = 0;
    std::vector<double> stored, work;  // E_e and W_e per effect
    template <class Archive>
    void serialize(Archive& ar) {
        ar(kinetic, stored, work);
    }
};

/// Energy bookkeeping of the run, one CSV row per observation. The work-energy theorem for the
/// nodes, dKE = sum_e W_e, with W_e = int F_e . v dt the work effect e of the pipeline does on them
/// (System work accounting, which this observer asks the run to switch on: it integrates W_e with
/// the integrator's own stage weights, to the integrator's order). An effect that stores elastic
/// energy E_e (Effect::potential_energy) splits its work into a change of E_e and the rest:
///
///     bulk effects and friction laws   dissipated   D_e = -W_e - dE_e   (springs: ~0; dashpots: E = 0)
///     loaders                          input        I_e =  W_e + dE_e   (driving spring: int F_S V dt;
///                                                                        normal load: its work, E = 0;
///                                                                        base contact: ~0, it is rigid)
///
/// d is the change since the first observation, which is the reference state of every column. The
/// kind of an effect (Loader, FrictionLaw, else the bulk model's) decides its group. An effect that
/// is switched off in some stage should report no stored energy there (the driving spring stores
/// none before its first stage), else its E_e would change with no work and show as D_e or I_e.
///
/// Columns (J unless stated; <label> is System::labels(): the scene type of a loader or friction
/// law, the key() of a bulk effect, e.g. lattice_springs, bond_damping):
///
///     time (s), step, stage           as in loading_curve
///     kinetic_energy                  KE = 1/2 sum_i m_i |v_i|^2
///     <label>_energy                  E_e at the observed state
///     <label>_work                    W_e since the first observation
///     <label>_dissipated | _input     D_e (bulk effects, friction laws) or I_e (loaders), as above
///     stored_energy                   sum_e E_e
///     input                           sum of I_e over loaders
///     dissipated_damping              sum of D_e over the bulk model's effects: the bond dashpots,
///                                     plus the springs' time-integration error (their D_e ~ 0)
///     dissipated_friction             sum of D_e over friction laws (junction breaking and sliding)
///     residual                        dKE - sum_e W_e: the integrator's error in the work-energy
///                                     theorem (RK4: 4th order in dt); exactly 0 in continuous time
///     relative_residual               residual / input (NaN while input <= 0)
///     balance_error                   dKE + d(stored_energy) + dissipated_damping + dissipated_friction
///                                     - input: the balance "kinetic + stored + dissipated = input"
///                                     closed from the columns above; algebraically the residual
///                                     (so it checks the bookkeeping itself), equal to it up to round-off
///
/// Cost: every effect's potential_energy() once per observation, and the work accounting of every
/// force evaluation (one pass over the forces per effect and stage).
class EnergyBalance final : public Observer {
public:
    // Checkpoints: what changes as it observes (its tables are cut back and appended to by the run).
    bool checkpointable() const override { return true; }
    void save_state(StateOut& out) const override { out(*this); }
    void restore_state(StateIn& in) override { in(*this); }
    template <class Archive>
    void serialize(Archive& ar) {
        ar(reference_);
    }
    struct Params {
        std::string file = "energy.csv";
    };
    static constexpr std::string_view type = "energy";
    static ParamSpec<Params> spec();

    EnergyBalance(const Params& p, const Context&);
    bool needs_work_accounting() const override { return true; }
    void begin(const RunView& view) override;
    void observe(const RunView& view) override;

private:
    enum class Group { bulk, friction, loader };
    using Reference = EnergyReference;
    static double kinetic_energy(const RunView& view);

    Params params_;
    std::vector<const Effect*> effects_;  // System::for_each_effect() order, like labels() and work()
    std::vector<Group> groups_;
    std::optional<Reference> reference_;  // the first observation
    std::unique_ptr<TableWriter> table_;
    std::vector<double> row_, stored_;
};

}  // namespace frictionlab
