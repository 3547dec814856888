#pragma once
#include <string>
#include <string_view>

#include "stick_slip_law.hpp"

namespace frictionlab {

/// Amontons-Coulomb friction with static and kinetic thresholds per interface block: J. K. Trømborg,
/// J. Scheibert, D. S. Amundsen, K. Thøgersen, A. Malthe-Sørenssen, "Transition from static to
/// kinetic friction: insights from a 2D model", PRL 107, 074301 (2011),
/// doi:10.1103/PhysRevLett.107.074301; S. Maegawa, A. Suzuki, K. Nakano, Tribol. Lett. 38, 313
/// (2010), doi:10.1007/s11249-010-9611-7.
///
///     stuck     F = -k_t (x - anchor),   while |k_t (x - anchor)| <= mu_s f_N      (judged at commit)
///     slipping  F = -mu_d f_N tanh(v / v_r)                    (tanh: sign(v) made smooth, v_r tiny)
///     detached  F = 0                                          (f_N = 0)
///
/// on a 2D body's interface; on a 3D body's, x, v and F are vectors of its plane and the law is
/// isotropic, F = -mu_d f_N tanh(v.s / v_r) s while slipping, s the direction the block slides in
/// (StickSlipLaw, theory.md §0).
///
/// k_t = sqrt(39.2e9 N/m^2 f_N) per block unless given. Re-stick (StickSlipLaw, which holds the
/// block logic shared with slip_weakening): at a commit, when the velocity has reversed or fallen
/// below stick_velocity after exceeding it, with the spring re-anchored to carry the kinetic force
/// the block felt, so the friction force is continuous and the block re-loads from mu_d f_N.
/// Publishes "friction_force" and "slipping" (1 while slipping, else 0; StickSlipLaw).
class CoulombStrength {
public:
    struct Params {
        double mu_s = 0.4;
        double mu_d = 0.17;
        double tangential_stiffness = 0;
        double stick_velocity = 1e-5;
        double regularisation_velocity = 1e-6;
        std::string node_set = "interface";
    };

    static constexpr std::string_view type = "coulomb";
    static ParamSpec<Params> spec();

    explicit CoulombStrength(const Params&);

    /// S = mu_d f_N, whatever the slip.
    double operator()(double normal, double /*slip*/) const { return mu_d_ * normal; }
    double kinetic_coefficient() const { return mu_d_; }
    void declare(Quantities&, const std::string& /*node_set*/, Index /*blocks*/) {}  // no field of its own
    void publish(Index, stick_slip::Mode, double /*slip*/) {}
    std::string describe(const stick_slip::Settings&, const std::string& stiffness) const;

private:
    double mu_d_;
};

using Coulomb = StickSlipLaw<CoulombStrength>;

}  // namespace frictionlab
