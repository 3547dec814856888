#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/model/slider_params.hpp"
#include "cubic_bonds.hpp"

namespace frictionlab {

/// The elastic slider as a simple-cubic lattice of nx x ny x nz point masses, the 3D twin of
/// spring_lattice_2d: spacing a = L/(nx-1) = B/(ny-1) = H/(nz-1) (x along the length L, y across
/// the width B, z up the height H), node ix + nx (iy + ny iz) at (ix a, iy a, iz a), iz = 0 the
/// interface face. Every node is joined by geometric central springs to its 6 nearest neighbours
/// (stiffness k, rest length a) and to its 12 face-diagonal neighbours (the same k, rest length
/// sqrt(2) a), and a dashpot eta on every bond acts on the full relative velocity.
///
/// Elastic constants (long waves, interior, boundaries ignored). A uniform strain eps stretches a
/// bond of rest vector l n by l (n . eps n), so the energy per node is sum over half the
/// neighbours of k l^2 (n . eps n)^2 / 2, over the volume a^3 per node:
///     C_ijkl = (1/a^3) sum_{half neighbours} k l^2 n_i n_j n_k n_l.
/// Nearest neighbours (3 per node, l = a) give C11 = k1/a; face diagonals (6 per node, l^2 = 2a^2,
/// n_x^4 = 1/4 on 4 of them, n_x^2 n_y^2 = 1/4 on 2) give C11 += 2 k2/a, C12 = C44 = k2/a. With
/// k1 = k2 = k the lattice is isotropic (C11 - C12 = 2 C44), a Cauchy solid lambda = mu = k/a:
///     C11 = 3k/a, C12 = C44 = k/a,   E = 5k/(2a),   nu = 1/4,   so   k = 2 E a / 5,
/// and, with the lattice density rho = m/a^3,
///     c_P = sqrt(C11/rho) = a sqrt(3k/m),   c_S = sqrt(C44/rho) = a sqrt(k/m),   c_R = 0.9194 c_S.
/// The tests check these constants on the lattice's own forces (face tractions of uniform strains)
/// and the speeds on pulses.
///
/// The lattice size is a resolution, as in 2D (theory.md §1a): at reference_spacing a_ref the node
/// mass is M/(nx ny nz) and eta = sqrt(c k m); at another spacing the lattice keeps the density
/// and the viscosity of that reference lattice: m = m_ref (a/a_ref)^3 with m_ref = M/n_ref and
/// n_ref = (L/a_ref + 1)(B/a_ref + 1)(H/a_ref + 1), and eta = sqrt(c k_ref m_ref) (a/a_ref) (a bond
/// dashpot eta gives a viscosity ~ eta/a in 3D, where the 2D lattice's fixed width makes it ~ eta/B).
/// k = 2 E a / 5 follows the spacing by itself. reference_spacing 0 keeps the per-block values at every
/// spacing. As in 2D, edge and corner nodes are not lightened nor their springs halved, so the
/// lattice density is M/(LBH) times (nx-1)(ny-1)(nz-1)/(nx ny nz) at the reference spacing: 0.578 for
/// the default 41 x 3 x 9, whose wave speeds are therefore 31.5 % above those of M/(LBH) (2D: 0.867,
/// 7.4 %), and a bar's axial stiffness is that of a cross-section a^2 (ny nz - 0.3 (ny + nz)), not
/// B H = a^2 (ny - 1)(nz - 1) (23.4 a^2 against 16 a^2 at 3 x 9). A thin lattice is far from its
/// continuum: the default is a coarse first resolution, not a converged slider.
///
/// The 2D lattice as a limit. Across a periodic width (across: periodic, B = ny a, one period of an
/// unbounded slider) a state that does not vary across the width is plane strain, and each layer of
/// nodes is then the 2D lattice of width a with E' = E/(1 - nu^2) = 16E/15: the straight bond and
/// the two face diagonals that leave it across the width act as one straight bond 2k = 3 a E'/4 = K,
/// the in-plane diagonals as K/2. With the small-strain law this holds exactly (the diagonals'
/// forces across the width cancel pair by pair), so one layer (ny = 1) moves as the 2D lattice to
/// round-off; the geometric law differs at second order in the strain. Body::bond_stiffness, which
/// loaders scale with (the base contact's K_b = K/2), is this K = 2k = 4Ea/5, so they reduce to the
/// 2D ones too. The dashpots do not: per layer the full-vector dashpots add up to 3 eta along each
/// straight bond (its own and the two diagonals across the width) against eta on the diagonals,
/// where the 2D lattice has eta on both.
///
/// Its cubes are Body::volumes, for pictures (the ParaView series draws them as hexahedra). Not yet:
/// the bond-projected dashpots of the 2D lattice.
class SpringLattice3d final : public BulkModel {
public:
    /// Across the width: two free side faces, or periodic (node iy = ny - 1 bonded to iy = 0 as to
    /// a neighbour, the width B = ny a one period of an unbounded slider: plane strain).
    enum class Across { bounded, periodic };
    struct Params : SliderParams {
        int nx = 41;
        int ny = 3;
        int nz = 9;
        double damping_factor = 0.5;        // c in eta = sqrt(c k m)
        double reference_spacing = 2.5e-3;  // a_ref, m; 0: per-block m and eta at every spacing
        Across across = Across::bounded;
        CubicLatticeSprings::Law springs = CubicLatticeSprings::Law::geometric;
    };
    static constexpr std::string_view type = "spring_lattice_3d";
    static ParamSpec<Params> spec();
    /// Why the lattice cells are not cubes, or "" if they are (L/(nx-1) = B/(ny-1) = H/(nz-1) to 1e-9;
    /// B/ny across a periodic width).
    static std::string spacing_mismatch(const Params& p);
    /// Why the lattice is too large to build (with the memory it would take), or "".
    static std::string too_large(const Params& p);

    /// Node mass m and bond dashpot eta (before the factor c: eta = sqrt(c) * damping_scale).
    struct NodeScales {
        double mass = 0;
        double damping_scale = 0;  // sqrt(k m) at the reference spacing, times a/a_ref
    };
    static NodeScales node_scales(const Params& p);

    SpringLattice3d(const Params& p, const Context& ctx);

    const Body& body() const override { return body_; }
    std::vector<std::unique_ptr<Effect>> effects(const Context& ctx) override;

    Index nx() const { return nx_; }
    Index ny() const { return ny_; }
    Index nz() const { return nz_; }
    Index node(Index ix, Index iy, Index iz) const { return ix + nx_ * (iy + ny_ * iz); }
    double node_mass() const { return body_.mass(0); }
    /// k, N/m: every spring's stiffness. Body::bond_stiffness, what loaders scale with, is 2k (see above).
    double spring_stiffness() const { return k_; }
    /// eta, N s/m; 0 when damping is off.
    double damping_coefficient() const { return eta_; }
    /// Every bond once, as a list (built on each call).
    std::vector<CubicBond> bonds() const { return families_->bonds(k_); }

private:
    void build_node_sets();
    void build_bonds();
    /// The lattice's cubes as Body::volumes, for pictures.
    void build_volumes();

    Index nx_, ny_, nz_;
    Body body_;
    std::shared_ptr<const CubicFamilies> families_;
    double k_ = 0, eta_ = 0;
    Across across_;
    CubicLatticeSprings::Law springs_;
};

}  // namespace frictionlab
