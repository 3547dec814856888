#pragma once
// What a bulk model exposes to loaders, friction laws and observers: reference geometry, masses,
// named node sets and the connectivity for pictures. Loaders and friction laws address nodes only
// through node sets, so they work on any bulk model that provides the sets they need.
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

struct Body {
    Eigen::ArrayXd x0, z0;                     // reference (undeformed) positions [nnode], m
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
    /// The slowest long-wave speed of the bulk (a lattice's c_S, a chain's one speed), m/s; 0:
    /// unknown. L / wave_speed is the time the body takes to ring: observers that must look past its
    /// vibrations (the rupture detector's slip rate) average over it.
    double wave_speed = 0;
    std::map<std::string, NodeSet, std::less<>> node_sets;
    std::vector<std::array<Index, 2>> bonds;  // springs, for pictures and bond-force output
    std::vector<std::array<Index, 4>> cells;  // quads, counter-clockwise; empty for a chain

    Index size() const { return x0.size(); }
    /// The named set; throws InputError listing the available sets if there is none.
    const NodeSet& nodes(std::string_view set) const;
};

}  // namespace frictionlab
