#include "spring_lattice_3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/body_size.hpp"

namespace frictionlab {

ParamSpec<SpringLattice3d::Params> SpringLattice3d::spec() {
    ParamSpec<Params> s(
        "Simple-cubic spring-block lattice, the 3D twin of spring_lattice_2d: geometric central springs k = 2Ea/5 to "
        "the 6 nearest and the 12 face-diagonal neighbours (isotropic, Poisson's ratio 1/4), equal masses, dashpots "
        "eta = sqrt(c k m) on every bond; a lattice finer or coarser than reference_spacing resolves the same "
        "continuum.");
    add_slider_params(s, "k = 2Ea/5 (nearest and face-diagonal neighbours alike, a the spacing)",
                      "shared equally by all nodes at reference_spacing (at another spacing the nodes keep that "
                      "lattice's density)");
    s.add("nx", &Params::nx, "Number of nodes along x (the length).").unit("1").at_least(2);
    s.add("ny", &Params::ny,
          "Number of nodes along y (the width): at least 2 between free side faces, at least 1 across a periodic "
          "width (one layer: the plane-strain slice of an unbounded slider).")
        .unit("1")
        .at_least(1);
    s.add("nz", &Params::nz,
          "Number of nodes along z (the height); L/(nx-1) = B/(ny-1) = H/(nz-1) must hold (B/ny across a periodic "
          "width).")
        .unit("1")
        .at_least(2);
    s.add("damping_factor", &Params::damping_factor,
          "Factor c in the bond dashpot eta = sqrt(c k m) acting on the full relative velocity, m the node mass "
          "and k the spring stiffness at reference_spacing; 0 switches bond damping off.")
        .unit("1")
        .at_least(0);
    s.add("reference_spacing", &Params::reference_spacing,
          "Spacing at which the node mass and the bond dashpot take the per-block values M/(nx ny nz) and "
          "sqrt(c k m); at another spacing the lattice keeps their density and viscosity (m ~ a^3, eta ~ a). 0: "
          "the per-block values at every spacing.")
        .unit("m")
        .at_least(0);
    s.choice("across", &Params::across, {{"bounded", Across::bounded}, {"periodic", Across::periodic}},
             "Across the width: bounded (two free side faces, spacing B/(ny-1)) or periodic (the last layer bonded "
             "to the first, spacing B/ny: one period of a slider unbounded across, in plane strain; with the "
             "small-strain springs one layer moves as spring_lattice_2d of width a and E' = 16E/15).");
    s.choice(
        "springs", &Params::springs,
        {{"geometric", CubicLatticeSprings::Law::geometric}, {"small_strain", CubicLatticeSprings::Law::small_strain}},
        "Spring law: geometric (exact for large rotations) or small_strain (linearised about the rest "
        "state, only for small rotations), as spring_lattice_2d's.");
    s.rule("ny", [](const Params& p) -> std::string {
        if (p.across == Across::bounded && p.ny < 2)
            return "a lattice bounded across its width needs ny >= 2 (or across: periodic for one layer)";
        return {};
    });
    s.rule("nz", spacing_mismatch);
    s.rule("nx", too_large);
    s.dimensions({3}, "a simple-cubic lattice in x, y and z");
    return s;
}

std::string SpringLattice3d::too_large(const Params& p) {
    // Measured: a run's peak memory grows by 2.8 kB a node (41 x ny x 9 with rk4 and Coulomb friction,
    // 1107 to 15129 nodes: the state and the stages, the bond families and their runs).
    constexpr double bytes_per_node = 2900;
    return body_too_large(static_cast<double>(p.nx) * static_cast<double>(p.ny) * static_cast<double>(p.nz),
                          bytes_per_node, "nx x ny x nz", "lattice");
}

std::string SpringLattice3d::spacing_mismatch(const Params& p) {
    const int gaps_y = p.across == Across::periodic ? p.ny : p.ny - 1;
    if (p.nx < 2 || gaps_y < 1 || p.nz < 2) return {};  // the per-key bounds report this
    const double along_x = p.length / (p.nx - 1), along_y = p.width / gaps_y, along_z = p.height / (p.nz - 1);
    const double largest = std::max({along_x, along_y, along_z}), smallest = std::min({along_x, along_y, along_z});
    if (largest - smallest <= 1e-9 * largest) return {};
    return fmt::format(
        "the lattice cells must be cubes: length/(nx-1) = {:.6g} m, width/{} = {:.6g} m, height/(nz-1) = {:.6g} m",
        along_x, p.across == Across::periodic ? "ny" : "(ny-1)", along_y, along_z);
}

SpringLattice3d::NodeScales SpringLattice3d::node_scales(const Params& p) {
    const double spacing = p.length / (p.nx - 1), reference = p.reference_spacing;
    const double stiffness = 0.4 * p.youngs_modulus * spacing;
    const double per_block = p.mass / (static_cast<double>(p.nx) * p.ny * p.nz);
    // At the reference spacing (to the cubic-cell check's tolerance) exactly the per-block values.
    if (reference <= 0 || std::abs(spacing - reference) <= 1e-9 * reference)
        return {per_block, std::sqrt(stiffness * per_block)};
    const double across = p.width / reference + (p.across == Across::periodic ? 0 : 1);
    const double reference_nodes = (p.length / reference + 1) * across * (p.height / reference + 1);
    const double reference_mass = p.mass / reference_nodes, ratio = spacing / reference;
    const double reference_stiffness = 0.4 * p.youngs_modulus * reference;
    return {reference_mass * ratio * ratio * ratio, std::sqrt(reference_stiffness * reference_mass) * ratio};
}

SpringLattice3d::SpringLattice3d(const Params& p, const Context& ctx)
    : nx_(p.nx), ny_(p.ny), nz_(p.nz), across_(p.across), springs_(p.springs) {
    spec().checked(p);
    const double a = p.length / (p.nx - 1);
    const Index n = nx_ * ny_ * nz_;
    // Across a periodic width the layers sit at iy a, iy < ny; the period B = ny a closes the ring.
    body_.reference_position.resize(n, 3);  // x, y, z
    for (Index iz = 0; iz < nz_; ++iz)
        for (Index iy = 0; iy < ny_; ++iy)
            for (Index ix = 0; ix < nx_; ++ix) {
                const Index i = node(ix, iy, iz);
                body_.reference_position(i, 0) = ix * a;
                body_.reference_position(i, 1) = iy * a;
                body_.reference_position(i, 2) = iz * a;
            }
    const NodeScales scales = node_scales(p);
    body_.mass = Eigen::ArrayXd::Constant(n, scales.mass);
    body_.length = p.length;
    body_.height = p.height;
    body_.width = p.width;
    body_.spacing = a;
    k_ = 0.4 * p.youngs_modulus * a;  // k = 2Ea/5
    body_.bond_stiffness = 2 * k_;    // the 2D lattice's K that a layer is in plane strain (header)
    body_.reference_spacing = p.reference_spacing;
    body_.contact_frame = ContactFrame::horizontal_base(3);
    body_.wave_speed = a * std::sqrt(k_ / scales.mass);  // c_S = sqrt(C44/rho) = a sqrt(k/m)
    eta_ = std::sqrt(p.damping_factor) * scales.damping_scale;
    build_node_sets();
    build_bonds();
    build_volumes();
    ctx.log.debug("{}: {}x{}x{} lattice{}, a = {:.4g} m, m = {:.4g} kg, k = {:.4g} N/m, eta = {:.4g} N s/m", ctx.name,
                  nx_, ny_, nz_, across_ == Across::periodic ? " (periodic across)" : "", a, node_mass(), k_, eta_);
}

void SpringLattice3d::build_node_sets() {
    // Each face in node order: along x first, then y, then z.
    auto face = [&](auto on_face) {
        NodeSet s;
        for (Index iz = 0; iz < nz_; ++iz)
            for (Index iy = 0; iy < ny_; ++iy)
                for (Index ix = 0; ix < nx_; ++ix)
                    if (on_face(ix, iz)) s.push_back(node(ix, iy, iz));
        return s;
    };
    body_.node_sets["all"] = face([](Index, Index) { return true; });
    body_.node_sets["interface"] = face([](Index, Index iz) { return iz == 0; });
    body_.node_sets["top"] = face([&](Index, Index iz) { return iz == nz_ - 1; });
    body_.node_sets["trailing_edge"] = face([](Index ix, Index) { return ix == 0; });
    body_.node_sets["leading_edge"] = face([&](Index ix, Index) { return ix == nx_ - 1; });
}

void SpringLattice3d::build_bonds() {
    families_ = std::make_shared<const CubicFamilies>(nx_, ny_, nz_, body_.spacing, across_ == Across::periodic);
    families_->for_each_bond(k_, [&](const CubicBond& b) {
        if (std::abs(b.image(1)) < body_.spacing / 2) body_.bonds.push_back({b.i, b.j});  // not across the period
    });
}

void SpringLattice3d::build_volumes() {
    // The cubes between neighbouring nodes; none across a periodic width's seam, which would span it.
    for (Index iz = 0; iz + 1 < nz_; ++iz)
        for (Index iy = 0; iy + 1 < ny_; ++iy)
            for (Index ix = 0; ix + 1 < nx_; ++ix)
                body_.volumes.push_back({node(ix, iy, iz), node(ix + 1, iy, iz), node(ix + 1, iy + 1, iz),
                                         node(ix, iy + 1, iz), node(ix, iy, iz + 1), node(ix + 1, iy, iz + 1),
                                         node(ix + 1, iy + 1, iz + 1), node(ix, iy + 1, iz + 1)});
}

std::vector<std::unique_ptr<Effect>> SpringLattice3d::effects(const Context&) {
    std::vector<std::unique_ptr<Effect>> out;
    auto springs = std::make_unique<CubicLatticeSprings>(
        families_, k_, fmt::format("{}x{}x{}{}", nx_, ny_, nz_, across_ == Across::periodic ? " periodic across" : ""),
        springs_);
    if (eta_ > 0)
        out.push_back(
            std::make_unique<CubicBonds>(std::move(springs), std::make_unique<CubicBondDamping>(families_, eta_)));
    else
        out.push_back(std::move(springs));
    return out;
}

}  // namespace frictionlab
