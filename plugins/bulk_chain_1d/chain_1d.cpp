#include "chain_1d.hpp"

#include <cmath>

#include "chain_damping.hpp"
#include "chain_springs.hpp"
#include "frictionlab/model/body_size.hpp"
#include "vertical_damping.hpp"

namespace frictionlab {

ParamSpec<Chain1d::Params> Chain1d::spec() {
    ParamSpec<Params> s(
        "1D chain of N blocks loaded from the side (Maegawa et al. 2010; Amundsen et al. 2012): masses M/N, "
        "springs k = E B H / a and an internal viscosity eta = sqrt(c k m) between neighbours, in x; every block "
        "is on the interface and on the top surface. doi:10.1007/s11249-011-9894-3");
    add_slider_params(s, "k = E B H / a between neighbours, a = L/(N-1)");
    s.add("blocks", &Params::blocks, "Number N of blocks along x.").unit("1").at_least(2);
    s.add("bond_stiffness", &Params::bond_stiffness,
          "Stiffness k of the spring between neighbouring blocks; 0 takes the bar's E B H / a.")
        .unit("N/m")
        .at_least(0);
    s.add("damping_factor", &Params::damping_factor,
          "Factor c of the internal viscosity, a dashpot eta = sqrt(c k m) between neighbours (the lattice's form; "
          "Amundsen et al. 2012); 0 switches it off.")
        .unit("1")
        .at_least(0);
    s.add("vertical_damping_factor", &Params::vertical_damping_factor,
          "Factor c_z of a vertical dashpot eta_z = sqrt(c_z k m) from each block to the base, so the blocks settle "
          "on their base contact (2: critical for K_b = k/2); 0 switches it off.")
        .unit("1")
        .at_least(0);
    s.rule("blocks", too_large);
    s.dimensions({2}, "blocks moving in x and z, in a row along x");
    return s;
}

std::string Chain1d::too_large(const Params& p) {
    // Measured: `check` of the Amundsen scene peaked at 451 MB with 1,000,000 blocks and at 872 MB
    // with 2,000,000, ~420 bytes per block.
    constexpr double bytes_per_node = 420;
    return body_too_large(p.blocks, bytes_per_node, "blocks", "chain");
}

Chain1d::Chain1d(const Params& p, const Context& ctx) {
    const Index n = spec().checked(p).blocks;
    const double a = p.length / (n - 1);
    body_.reference_position = planar_positions(Eigen::ArrayXd::LinSpaced(n, 0.0, p.length), Eigen::ArrayXd::Zero(n));
    body_.contact_frame = ContactFrame::horizontal_base(2);
    body_.mass = Eigen::ArrayXd::Constant(n, p.mass / n);
    body_.length = p.length;
    body_.height = p.height;
    body_.width = p.width;
    body_.spacing = a;
    body_.bond_stiffness = p.bond_stiffness > 0 ? p.bond_stiffness : p.youngs_modulus * p.width * p.height / a;
    body_.wave_speed = a * std::sqrt(body_.bond_stiffness / node_mass());
    eta_ = std::sqrt(p.damping_factor * body_.bond_stiffness * node_mass());
    eta_z_ = std::sqrt(p.vertical_damping_factor * body_.bond_stiffness * node_mass());

    NodeSet all(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i) all[static_cast<std::size_t>(i)] = i;
    body_.node_sets["all"] = all;
    body_.node_sets["interface"] = all;
    body_.node_sets["top"] = all;
    body_.node_sets["trailing_edge"] = {0};
    body_.node_sets["leading_edge"] = {n - 1};
    for (Index i = 0; i + 1 < n; ++i) body_.bonds.push_back({i, i + 1});
    ctx.log.debug(
        "{}: chain of {} blocks, a = {:.4g} m, m = {:.4g} kg, k = {:.4g} N/m, eta = {:.4g} N s/m, "
        "eta_z = {:.4g} N s/m",
        ctx.name, n, a, node_mass(), body_.bond_stiffness, eta_, eta_z_);
}

std::vector<std::unique_ptr<Effect>> Chain1d::effects(const Context&) {
    std::vector<std::unique_ptr<Effect>> out;
    out.push_back(std::make_unique<ChainSprings>(body_.size(), body_.spacing, body_.bond_stiffness));
    if (eta_ > 0) out.push_back(std::make_unique<ChainDamping>(body_.size(), eta_));
    if (eta_z_ > 0) out.push_back(std::make_unique<VerticalDamping>(eta_z_));
    return out;
}

}  // namespace frictionlab
