#pragma once
// A body of point masses for the tests of the dimension-generic core, in 2D or in 3D: nx x nz
// nodes (2D, axes x, z) or nx x ny x nz nodes (3D, axes x, y, z), a spacing a apart, each of mass m,
// node ix + nx (iy + ny iz), with
//   - central springs k between nearest neighbours, geometric: F_i = k (1 - a/r) d, d = x_j - x_i;
//   - a ground spring k0 and dashpot c0 on every node along every axis to its reference position
//     (a body held in place elastically: every mode restored and damped, the stiffness positive
//     definite), if k0 > 0 or c0 > 0;
//   - a dashpot c on every bond, c (v_j - v_i) on node i, if c > 0.
// Linearised about rest, a bond along an axis is stiff only along it, so motion along each axis
// couples only through the bonds along that axis: the normal modes are those of the chains along
// the axes. A chain of n nodes with free ends has
//     omega_j^2 = k0/m + (4 k/m) sin^2(j pi / (2 n)),   shape cos(j pi (i + 1/2) / n),   j = 0 .. n-1,
// the same shape on every chain along that axis.
//
// The interface is the bottom layer (iz = 0), its contact frame that of a base below (normal z).
#include <memory>
#include <string_view>
#include <vector>

#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/model/kinds.hpp"

namespace frictionlab::testing {

class TestLattice final : public BulkModel {
public:
    struct Params {
        int dimension = 3;
        int nx = 4, ny = 3, nz = 2;   // ny: 3D only
        double spacing = 1e-3;        // a, m
        double mass = 1e-3;           // m per node, kg
        double stiffness = 1e4;       // k, N/m
        double ground_stiffness = 0;  // k0, N/m
        double ground_damping = 0;    // c0, N s/m
        double damping = 0;           // c, N s/m
    };
    static constexpr std::string_view type = "test_lattice";
    static ParamSpec<Params> spec();

    TestLattice(const Params& p, const Context& ctx);
    const Body& body() const override { return body_; }
    std::vector<std::unique_ptr<Effect>> effects(const Context&) override;

    const Params& params() const { return p_; }
    /// Node ix + nx (iy + ny iz); iy = 0 in 2D.
    Index node(Index ix, Index iy, Index iz) const { return ix + p_.nx * (iy + ny() * iz); }
    Index ny() const { return p_.dimension == 3 ? p_.ny : 1; }
    /// The nodes along `axis` (the chain's length) and omega of its mode j (free ends).
    Index chain_length(int axis) const;
    double mode_frequency(int axis, int j) const;
    /// The shape of mode j along `axis` at node i: cos(j pi (i_axis + 1/2) / n).
    double mode_shape(int axis, int j, Index node) const;

private:
    /// The index of node `node` along `axis` (ix, iy or iz; z is the last axis).
    Index position_along(Index node, int axis) const;

    Params p_;
    Body body_;
    std::vector<std::array<Index, 2>> bonds_;
};

}  // namespace frictionlab::testing
