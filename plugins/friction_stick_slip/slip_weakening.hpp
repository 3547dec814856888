#pragma once
#include <algorithm>
#include <string>
#include <string_view>

#include "stick_slip_law.hpp"

namespace frictionlab {

/// Linear slip-weakening friction per interface block: D. S. Kammer, V. A. Yastrebov, G. Anciaux,
/// J.-F. Molinari, "The existence of a critical length scale in regularised friction", JMPS 63, 40
/// (2014), doi:10.1016/j.jmps.2013.10.007. A regression partner for coulomb: the
/// same stuck spring, breaking and re-stick (StickSlipLaw), with a strength that weakens with slip
///
///     tau(delta) = [mu_s - (mu_s - mu_d) min(delta / D_c, 1)] f_N
///     slipping  F = -tau(delta) tanh(v / v_r)        (tanh: sign(v) made smooth, v_r tiny)
///
/// delta is the slip accumulated since the block last stuck (within a step delta_n + |x - x_n|).
/// A block breaks at mu_s f_N = tau(0), so the force does not drop on breaking: it weakens over D_c.
/// Publishes "friction_force" and "slip" (delta; 0 while stuck or detached).
class SlipWeakeningStrength {
public:
    struct Params {
        double mu_s = 0.4;
        double mu_d = 0.17;
        double critical_slip = 1e-6;
        double tangential_stiffness = 0;
        double stick_velocity = 1e-5;
        double regularisation_velocity = 1e-6;
        std::string node_set = "interface";
    };

    static constexpr std::string_view type = "slip_weakening";
    static ParamSpec<Params> spec();

    explicit SlipWeakeningStrength(const Params&);

    /// tau(delta).
    double operator()(double normal, double slip) const {
        const double weakened = std::min(slip / critical_slip_, 1.0);
        return (mu_s_ - (mu_s_ - mu_d_) * weakened) * normal;
    }
    double kinetic_coefficient() const { return mu_d_; }
    void declare(Quantities& q, const std::string& node_set, Index blocks);
    void publish(Index i, stick_slip::Mode /*mode*/, double slip) { (*slip_)[i] = slip; }
    std::string describe(const stick_slip::Settings&, const std::string& stiffness) const;

private:
    double mu_s_, mu_d_, critical_slip_;
    Eigen::ArrayXd* slip_ = nullptr;
};

using SlipWeakening = StickSlipLaw<SlipWeakeningStrength>;

}  // namespace frictionlab
