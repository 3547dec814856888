#pragma once
// What a bulk model exposes to loaders, friction laws and observers: its spatial dimension,
// reference geometry, masses, the contact frame of its interface, named node sets and the
// connectivity for pictures. Loaders and friction laws address nodes only through node sets and
// axes only through the contact frame, so they work on any bulk model that provides what they need.
//
// Standard node sets (share/docs/glossary.md): "all", "top", "interface" (bottom row, in contact with the
// base, ordered by increasing x), "trailing_edge" (x = 0 column, ordered by increasing z),
// "leading_edge" (x = L column, ordered by increasing z).
#include <array>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "frictionlab/model/state.hpp"

namespace frictionlab {

using NodeSet = std::vector<Index>;

/// The first node of a set whose nodes are consecutive (first, first + 1, ...), else -1: an effect
/// may then work on the set as one block of the state arrays instead of node by node.
Index consecutive_start(const NodeSet& set);

/// The axes of the interface's contact at each of its nodes: the normal, out of the base into the
/// body, and the tangential axes of the interface plane, the first of them the sliding direction.
/// The base is a plane, so one frame holds at every interface node, and it is made of the body's
/// axes, so that a contact acts on the whole array of one axis and a friction law on those of the
/// tangential ones, rotating nothing node by node (theory.md §0).
struct ContactFrame {
    int normal = 1;                  // the axis along the normal (2D: z)
    std::vector<int> tangential{0};  // the axes in the interface plane, the sliding direction first (2D: x)

    /// A base below the body: the normal the body's last axis (z), the tangential axes the others,
    /// x first: in 2D (x, z) normal z, tangential x; in 3D (x, y, z) normal z, tangential x, y.
    static ContactFrame horizontal_base(int dimension);
    /// Why the frame cannot be a frame of a body of `dimension` axes; empty if it can.
    std::string problem(int dimension) const;
};

struct Body {
    /// Reference (undeformed) positions [nnode, ndim], m: column a is axis a, (x, z) in 2D, (x, y, z)
    /// in 3D. Its column count is the body's spatial dimension, which the state's layout follows.
    Eigen::ArrayXXd reference_position;
    Eigen::ArrayXd mass;                       // [nnode], kg
    double length = 0, height = 0, width = 0;  // L (x), H (z), B (y), m
    double spacing = 0;                        // rest spacing of neighbouring nodes l_s, m
    /// Stiffness K of the bulk's nearest-neighbour springs (N/m): boundary effects that the model
    /// defines relative to it (the paper's base contact K_b = K/2) read it from here.
    double bond_stiffness = 0;
    /// Spacing at which the bulk's per-block values are the model's (spring_lattice_2d's
    /// reference_spacing), m; 0: none. Boundary effects the model gives per node (the base contact)
    /// scale from it to stay the same per unit area on another lattice.
    double reference_spacing = 0;
    /// The interface's contact frame; a bulk model other than a 2D one with its base below sets it.
    ContactFrame contact_frame;
    /// The slowest long-wave speed of the bulk (a lattice's c_S, a chain's one speed), m/s; 0:
    /// unknown. L / wave_speed is the time the body takes to ring: observers that must look past its
    /// vibrations (the rupture detector's slip rate) average over it.
    double wave_speed = 0;
    std::map<std::string, NodeSet, std::less<>> node_sets;
    std::vector<std::array<Index, 2>> bonds;  // springs, for pictures and bond-force output
    std::vector<std::array<Index, 4>> cells;  // 2D: quads, counter-clockwise; empty for a chain or a 3D body
    /// 3D: hexahedra, their corners in VTK_HEXAHEDRON's order (the face at the lowest z counter-clockwise
    /// seen from above, then the one above it); empty in 2D. For pictures, as `cells`.
    std::vector<std::array<Index, 8>> volumes;

    Index size() const { return reference_position.rows(); }
    int dimension() const { return static_cast<int>(reference_position.cols()); }
    /// Readable aliases of the reference positions along the axes every body has (StageView's x, z).
    auto x0() const { return reference_position.col(0); }
    auto z0() const { return reference_position.col(reference_position.cols() - 1); }
    /// The named set; throws InputError listing the available sets if there is none.
    const NodeSet& nodes(std::string_view set) const;
};

/// Reference positions [nnode, 2] of a planar body from its x and z columns.
Eigen::ArrayXXd planar_positions(const Eigen::ArrayXd& x, const Eigen::ArrayXd& z);

}  // namespace frictionlab
