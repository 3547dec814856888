#pragma once
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
class SlipWeakening final : public StickSlipLaw {
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

    SlipWeakening(const Params&, const Context&);

    std::string describe() const override;
    double kinetic_strength(double normal, double slip) const override;

private:
    void publish(Index i, const Block& b, double slip) override;

    double mu_d_, critical_slip_;
    Eigen::ArrayXd* slip_;
};

}  // namespace frictionlab
