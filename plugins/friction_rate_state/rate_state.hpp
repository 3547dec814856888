#pragma once
#include <string>
#include <string_view>

#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"

namespace frictionlab {

/// Rate-and-state friction per interface block (J. H. Dieterich, J. Geophys. Res. 84, 2161 (1979),
/// doi:10.1029/JB084iB05p02161; A. Ruina, J. Geophys. Res. 88, 10359 (1983),
/// doi:10.1029/JB088iB12p10359) in the regularised (arcsinh) form of theory.md D.2.4
/// (Rice & Ben-Zion 1996; Lapusta et al. 2000), with the state variable psi integrated as an aux
/// variable of the state vector, inside the integrator's stages, one slot per block:
///
///     F_i  = -mu(v_i, psi_i) f_N,i,          mu(v, psi) = a asinh[(v / (2 v0)) exp(psi / a)]
///     aging   dpsi/dt = (b v0 / D_c) [exp((f0 - psi) / b) - |v| / v0]
///     slip    dpsi/dt = -(|v| / D_c) [psi - psi_ss(v)]
///     psi_ss(v) = f0 - b ln(|v| / v0)                                (both laws, exactly)
///
/// v is the block's x-velocity relative to the (resting) base and f_N,i the quantity "normal_force"
/// at the same stage. mu is odd in v (asinh), so the force opposes the motion in either direction.
/// The psi form follows from the classical state theta by psi = f0 + b ln(v0 theta / D_c), which
/// makes the regularised mu equal f0 + a ln(v/v0) + b ln(v0 theta/D_c) wherever (v/2v0) e^(psi/a) >> 1:
/// aging d theta/dt = 1 - v theta/D_c gives the first law above; slip d theta/dt =
/// -(v theta/D_c) ln(v theta/D_c), with v theta/D_c = (v/v0) exp((psi - f0)/b), gives the second
/// (at v = 0 it neither heals nor weakens).
///
/// Steady state at speed v: mu_ss(v) = a asinh[(v/2v0) exp(f0/a) (v/v0)^(-b/a)], which is
/// f0 + (a - b) ln(v/v0) up to a relative O(X^-2), X = (v/v0) exp(f0/a) (v/v0)^(-b/a) (the argument
/// 2X of the logarithm; X ~ 1e31 at the defaults). initialise_aux puts every block at psi_ss of
/// `initial_velocity`. A single block pulled through a spring k slides steadily iff
/// k > k_c = f_N (b - a) / D_c (quasi-static; inertia raises it by m V^2 / (f_N a D_c)).
///
/// The law is smooth: no discrete state, no events, nothing to commit; it stores no energy.
class RateState final : public FrictionLaw {
public:
    bool checkpointable() const override { return true; }  // its state variable is in the state vector
    enum class Law { aging, slip };
    struct Params {
        double a = 0.008;
        double b = 0.012;
        double d_c = 1e-6;
        double f0 = 0.6;
        double v0 = 1e-6;
        double initial_velocity = 1e-9;
        Law law = Law::aging;
        std::string node_set = "interface";
    };

    static constexpr std::string_view type = "rate_state";
    static ParamSpec<Params> spec();

    RateState(const Params&, const Context&);

    /// mu(v, psi), the friction coefficient.
    double coefficient(double v, double psi) const;
    /// dpsi/dt at (v, psi) for the chosen evolution law.
    double state_rate(double v, double psi) const;
    /// psi_ss(v) = f0 - b ln(|v| / v0), the steady state of both laws.
    double steady_state(double v) const;
    /// mu(v, psi_ss(v)).
    double steady_coefficient(double v) const { return coefficient(v, steady_state(v)); }

    std::string describe() const override;
    void add_forces(const StageView& s, ForceView& f) override;
    void initialise_aux(Eigen::Ref<Eigen::ArrayXd> aux) const override;
    /// The force of block i depends on its own vx only, with dF/dv = -f_N a / sqrt(v^2 + w^2),
    /// w = 2 v0 exp(-psi/a): f_N a/|v| while sliding, f_N a/w at rest (5e41 N s/m at the defaults, f_N = 10 N).
    /// imex_euler takes it implicitly; an explicit step would need h f_N a / (m |v|) < ~2.
    bool has_velocity_jacobian() const override { return true; }
    void add_velocity_jacobian(const StageView& s, LocalVelocityJacobian& j) const override;
    std::string needs_implicit_velocity() const override {
        return "rate_state is too stiff in the slip velocity near rest for an explicit step (dF/dv = f_N a / w, "
               "theory.md D.2.4)";
    }
    /// dmu/dv at (v, psi) = a / sqrt(v^2 + w^2).
    double coefficient_slope(double v, double psi) const;

    Index blocks() const { return static_cast<Index>(nodes_.size()); }
    /// First aux slot of this law (block i's psi is aux[aux_offset() + i]).
    Index aux_offset() const { return offset_; }

private:
    Params p_;
    Law law_;
    NodeSet nodes_;
    Index offset_;
    const Eigen::ArrayXd* normal_force_;
    Eigen::ArrayXd *friction_force_, *state_;
};

}  // namespace frictionlab
