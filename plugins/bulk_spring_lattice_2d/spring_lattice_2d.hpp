#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/model/slider_params.hpp"
#include "bond_damping.hpp"
#include "lattice_grid.hpp"
#include "lattice_springs.hpp"

namespace frictionlab {

/// The elastic slider as a square lattice of N = nx nz point masses m = M/N (edge and corner
/// nodes are not lightened, theory.md B.20) with spacing l_s = L/(nx-1) = H/(nz-1), joined by
/// central springs to their 4 nearest neighbours (stiffness K = 3BE/4, rest length l_s) and to their
/// 4 next-nearest neighbours (K/2, sqrt(2) l_s), plus a dashpot eta = sqrt(c K m) on every bond
/// (Li2020 Eqs. 1, 2, 6).
///
/// The lattice size is a resolution (theory.md §1a): m and eta take these values at
/// reference_spacing l_ref (the paper's 41 x 9). At another spacing the lattice keeps their density
/// and viscosity, m = m_ref (l_s/l_ref)^2 and eta = sqrt(c K m_ref), with m_ref = M/n_ref and
/// n_ref = (L/l_ref + 1)(H/l_ref + 1) the reference lattice's nodes; K = 3BE/4 is the same at any
/// spacing. reference_spacing 0 keeps the per-block values at every spacing, as Li2020 prints them. The springs give
/// plane-stress constants C11 = 9E/8, C12 = C44 = 3E/8, i.e. Young's modulus E and Poisson's ratio exactly 1/3
/// (theory.md A.2); long-wave speeds c_L = sqrt(9E/8 rho), c_S = sqrt(3E/8 rho) with the lattice density rho = m/(l_s^2
/// B).
///
/// Two consequences of not halving boundary masses and springs: rho is M/(LHB) times
/// (nx-1)(nz-1)/(nx nz) (0.867 for 41x9, so wave speeds are 7.4 % above those of M/(LHB):
/// c_L = 1816 m/s, c_S = 1049 m/s), and under uniaxial stress sigma the end faces carry
/// sigma B (H + 3 l_s/4), the full straight springs of the top and bottom rows acting like an extra
/// quarter-spacing of material.
///
/// Node ix + nx*iz sits at (ix l_s, iz l_s); iz = 0 is the interface row. Boundary forces (load,
/// driving spring, base contact) are separate loaders acting on the node sets named here.
///
/// Li, Zhao, Xiong, Liu, Acta Mech. Sin. 36 (2020), doi:10.1007/s10409-020-00955-2;
/// Tromborg, Scheibert, Amundsen, Thogersen, Malthe-Sorenssen, PRL 107, 074301 (2011).
class SpringLattice2d final : public BulkModel {
public:
    struct Params : SliderParams {
        int nx = 41;
        int nz = 9;
        double damping_factor = 0.5;        // c in eta = sqrt(c K m)
        double reference_spacing = 2.5e-3;  // l_ref, m; 0: per-block m and eta at every spacing
        BondDamping::Mode damping_mode = BondDamping::Mode::full_vector;
        LatticeSprings::Law springs = LatticeSprings::Law::geometric;
    };
    static constexpr std::string_view type = "spring_lattice_2d";
    static ParamSpec<Params> spec();
    /// Why the lattice cells are not square, or "" if they are (L/(nx-1) = H/(nz-1) to 1e-9).
    static std::string spacing_mismatch(const Params& p);
    /// Why the lattice is too large to build (with the memory it would take), or "".
    static std::string too_large(const Params& p);

    /// Node mass m and bond dashpot eta of a lattice (see the class comment), eta before c is applied:
    /// sqrt(K m_ref).
    struct NodeScales {
        double mass = 0;
        double damping_mass = 0;  // m_ref: the mass in eta = sqrt(c K m_ref)
    };
    static NodeScales node_scales(const Params& p);

    SpringLattice2d(const Params& p, const Context& ctx);

    const Body& body() const override { return body_; }
    std::vector<std::unique_ptr<Effect>> effects(const Context& ctx) override;

    double node_mass() const { return body_.mass(0); }
    /// eta = sqrt(c K m), N s/m; 0 when damping is off.
    double damping_coefficient() const { return eta_; }
    const LatticeGrid& grid() const { return grid_; }

private:
    void build_node_sets();
    void build_connectivity();

    LatticeSprings::Law law_;
    BondDamping::Mode damping_mode_;
    LatticeGrid grid_;
    Body body_;
    double eta_ = 0;
};

}  // namespace frictionlab
