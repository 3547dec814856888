#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/model/slider_params.hpp"

namespace frictionlab {

/// The slider as a 1D chain of N blocks along the interface (Maegawa et al. 2010; Amundsen et al.
/// 2012): block i of mass m = M/N at x = i a, a = L/(N-1), joined to its neighbours by springs
/// k = E B H / a (a bar of cross-section B H cut into lengths a; a parameter may override it) and
/// dashpots eta = sqrt(c k m) (the internal viscosity, given as a factor c like the lattice's):
///
///     m x_i'' = k (u_{i+1} - 2 u_i + u_{i-1}) + eta (u'_{i+1} - 2 u'_i + u'_{i-1}) + boundary forces,
///     m z_i'' = -eta_z z_i' + boundary forces,   eta_z = sqrt(c_z k m)
///
/// Long waves travel at c = a sqrt(k/m) = sqrt(E/rho) sqrt(N/(N-1)) (rho = M/(LBH)); the discrete
/// chain's dispersion is omega(q) = 2 sqrt(k/m) |sin(q a/2)|.
///
/// Every block is on the interface and on the top surface, so the loaders of the lattice act on it
/// unchanged: normal_load presses each block, rigid_base_contact holds it (f_N = F_N/N at rest for a
/// uniform load), a friction law acts on it, and driving_spring pulls the trailing block (node set
/// "trailing_edge" is block 0 alone, whatever the height h: the torque F_S h of a driving point
/// above the interface is not modelled). The vertical dashpot eta_z to the base is not in Amundsen's
/// model: the chain has no vertical structure, and without it a block would bounce on its base
/// contact for ever; with rigid_base_contact's default K_b = k/2, c_z = 2 damps that critically.
///
/// Amundsen, Scheibert, Thøgersen, Trømborg, Malthe-Sørenssen, Tribol. Lett. 45, 357 (2012),
/// doi:10.1007/s11249-011-9894-3; Maegawa, Suzuki, Nakano, Tribol. Lett. 38, 313 (2010),
/// doi:10.1007/s11249-010-9611-7.
class Chain1d final : public BulkModel {
public:
    struct Params : SliderParams {
        int blocks = 100;                    // N
        double bond_stiffness = 0;           // k, N/m; 0: E B H / a
        double damping_factor = 0.5;         // c in eta = sqrt(c k m)
        double vertical_damping_factor = 2;  // c_z in eta_z = sqrt(c_z k m)
    };
    static constexpr std::string_view type = "chain_1d";
    static ParamSpec<Params> spec();
    /// Why the chain is too long to build (with the memory it would take), or "".
    static std::string too_large(const Params& p);

    Chain1d(const Params& p, const Context& ctx);

    const Body& body() const override { return body_; }
    std::vector<std::unique_ptr<Effect>> effects(const Context& ctx) override;

    double node_mass() const { return body_.mass(0); }
    /// eta = sqrt(c k m), N s/m.
    double damping_coefficient() const { return eta_; }
    /// eta_z = sqrt(c_z k m), N s/m.
    double vertical_damping_coefficient() const { return eta_z_; }

private:
    Body body_;
    double eta_ = 0, eta_z_ = 0;
};

}  // namespace frictionlab
