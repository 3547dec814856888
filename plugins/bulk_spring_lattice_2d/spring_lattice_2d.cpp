#include "spring_lattice_2d.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/body_size.hpp"
#include "lattice_bonds.hpp"

namespace frictionlab {

ParamSpec<SpringLattice2d::Params> SpringLattice2d::spec() {
    ParamSpec<Params> s(
        "Square spring-block lattice with diagonal springs (Li et al. 2020, Eqs. 1, 2, 6): straight "
        "springs K = 3BE/4, diagonals K/2 (Poisson's ratio 1/3), equal masses M/N, dashpots "
        "eta = sqrt(c K m) on every bond; a lattice finer or coarser than reference_spacing resolves the same "
        "continuum. doi:10.1007/s10409-020-00955-2");
    add_slider_params(s, "K = 3BE/4 (straight) and K/2 (diagonal)",
                      "shared equally by all nodes at reference_spacing (at another spacing the nodes keep that "
                      "lattice's density)");
    s.add("nx", &Params::nx, "Number of node columns along x.").unit("1").at_least(2);
    s.add("nz", &Params::nz, "Number of node rows along z; L/(nx-1) must equal H/(nz-1).").unit("1").at_least(2);
    s.add("damping_factor", &Params::damping_factor,
          "Factor c in the bond dashpot eta = sqrt(c K m) (0.5 in Li2020, 0.1 in Tromborg 2014), m the node mass at "
          "reference_spacing; 0 switches bond damping off.")
        .unit("1")
        .at_least(0);
    s.add("reference_spacing", &Params::reference_spacing,
          "Spacing at which the node mass and the bond dashpot take the per-block values M/(nx nz) and "
          "sqrt(c K m) (the paper's 41 x 9 slider); at another spacing the lattice keeps their density and "
          "viscosity, so that a finer lattice resolves the same continuum (theory.md 1a). 0: the per-block values "
          "at every spacing, as Li2020 prints them.")
        .unit("m")
        .at_least(0);
    s.choice("damping_mode", &Params::damping_mode,
             {{"full_vector", BondDamping::Mode::full_vector}, {"bond_projected", BondDamping::Mode::bond_projected}},
             "full_vector: eta (v_j - v_i) (Li2020 Eq. 2 as read in theory.md B.4); bond_projected: only the "
             "component along the current bond, which leaves rigid rotation undamped.");
    s.choice("springs", &Params::springs,
             {{"geometric", LatticeSprings::Law::geometric}, {"small_strain", LatticeSprings::Law::small_strain}},
             "geometric: Li2020 Eq. 1, exact for large rotations; small_strain: linearised about the reference "
             "configuration, cheaper, for small rotations only.");
    s.rule("nz", spacing_mismatch);
    s.rule("nx", too_large);
    s.dimensions({2}, "a plane-stress lattice in x and z");
    return s;
}

std::string SpringLattice2d::too_large(const Params& p) {
    // Measured: a 4,000,001 x 3 lattice took 5.2 GB before its first step, ~430 bytes per node.
    constexpr double bytes_per_node = 430;
    return body_too_large(static_cast<double>(p.nx) * static_cast<double>(p.nz), bytes_per_node, "nx x nz", "lattice");
}

std::string SpringLattice2d::spacing_mismatch(const Params& p) {
    if (p.nx < 2 || p.nz < 2) return {};  // the per-key bounds report this
    const double along_x = p.length / (p.nx - 1), along_z = p.height / (p.nz - 1);
    if (std::abs(along_x - along_z) <= 1e-9 * std::max(along_x, along_z)) return {};
    return fmt::format("the lattice cells must be square: length/(nx-1) = {:.6g} m but height/(nz-1) = {:.6g} m",
                       along_x, along_z);
}

SpringLattice2d::NodeScales SpringLattice2d::node_scales(const Params& p) {
    const double spacing = p.length / (p.nx - 1), reference = p.reference_spacing;
    const double per_block = p.mass / (static_cast<double>(p.nx) * p.nz);
    // At the reference spacing (to the square-cell check's tolerance) exactly the per-block values.
    if (reference <= 0 || std::abs(spacing - reference) <= 1e-9 * reference) return {per_block, per_block};
    const double reference_nodes = (p.length / reference + 1) * (p.height / reference + 1);
    const double reference_mass = p.mass / reference_nodes;
    const double ratio = spacing / reference;
    return {reference_mass * ratio * ratio, reference_mass};
}

SpringLattice2d::SpringLattice2d(const Params& p, const Context& ctx)
    : law_(spec().checked(p).springs), damping_mode_(p.damping_mode) {
    grid_ = {p.nx, p.nz, p.length / (p.nx - 1)};
    const Index n = grid_.size();
    body_.reference_position.resize(n, 2);  // x, z
    body_.contact_frame = ContactFrame::horizontal_base(2);
    for (Index iz = 0; iz < grid_.nz; ++iz)
        for (Index ix = 0; ix < grid_.nx; ++ix) {
            body_.reference_position(grid_.node(ix, iz), 0) = ix * grid_.spacing;
            body_.reference_position(grid_.node(ix, iz), 1) = iz * grid_.spacing;
        }
    const NodeScales scales = node_scales(p);
    body_.mass = Eigen::ArrayXd::Constant(n, scales.mass);
    body_.length = p.length;
    body_.height = p.height;
    body_.width = p.width;
    body_.spacing = grid_.spacing;
    body_.bond_stiffness = 0.75 * p.width * p.youngs_modulus;
    body_.reference_spacing = p.reference_spacing;
    body_.wave_speed = grid_.spacing * std::sqrt(body_.bond_stiffness / (2 * scales.mass));  // c_S = sqrt(3E/8 rho)
    eta_ = std::sqrt(p.damping_factor * body_.bond_stiffness * scales.damping_mass);
    build_node_sets();
    build_connectivity();
    ctx.log.debug("{}: {}x{} lattice, l_s = {:.4g} m, m = {:.4g} kg, K = {:.4g} N/m, eta = {:.4g} N s/m", ctx.name,
                  grid_.nx, grid_.nz, grid_.spacing, node_mass(), body_.bond_stiffness, eta_);
}

void SpringLattice2d::build_node_sets() {
    auto row = [&](Index iz) {
        NodeSet s;
        for (Index ix = 0; ix < grid_.nx; ++ix) s.push_back(grid_.node(ix, iz));
        return s;
    };
    auto column = [&](Index ix) {
        NodeSet s;
        for (Index iz = 0; iz < grid_.nz; ++iz) s.push_back(grid_.node(ix, iz));
        return s;
    };
    NodeSet all(grid_.size());
    for (Index i = 0; i < grid_.size(); ++i) all[i] = i;
    body_.node_sets["all"] = std::move(all);
    body_.node_sets["interface"] = row(0);
    body_.node_sets["top"] = row(grid_.nz - 1);
    body_.node_sets["trailing_edge"] = column(0);
    body_.node_sets["leading_edge"] = column(grid_.nx - 1);
}

void SpringLattice2d::build_connectivity() {
    for (const BondFamily& b : grid_.families())
        for (Index i = 0; i < b.count; ++i)
            if (b.mask[static_cast<std::size_t>(i)] != 0) body_.bonds.push_back({i, i + b.offset});
    for (Index iz = 0; iz + 1 < grid_.nz; ++iz)
        for (Index ix = 0; ix + 1 < grid_.nx; ++ix)
            body_.cells.push_back(
                {grid_.node(ix, iz), grid_.node(ix + 1, iz), grid_.node(ix + 1, iz + 1), grid_.node(ix, iz + 1)});
}

std::vector<std::unique_ptr<Effect>> SpringLattice2d::effects(const Context&) {
    auto springs = std::make_unique<LatticeSprings>(grid_, body_.bond_stiffness, law_);
    std::vector<std::unique_ptr<Effect>> out;
    if (eta_ > 0)
        out.push_back(std::make_unique<LatticeBonds>(std::move(springs),
                                                     std::make_unique<BondDamping>(grid_, eta_, damping_mode_)));
    else
        out.push_back(std::move(springs));
    return out;
}

}  // namespace frictionlab
