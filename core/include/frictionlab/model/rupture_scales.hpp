#pragma once
// The scales a rupture detector (observer `precursors`, theory.md §5a) derives its settings from,
// published by the components that know them, so that the detector carries over to another drive,
// friction law or lattice without constants tuned on one scene:
//
//   drive_velocity        (loaders that drive)  |V| of the drive's far end, m/s
//   characteristic_slip   (friction laws)       the slip a contact takes, from unloaded, before it
//                                               breaks (mu_s p / k_s of a junction, mu_s f_N / k_t of
//                                               a stuck spring; D_c of a law without elastic contact),
//                                               m; NaN until known: a law whose scale follows the
//                                               normal force sets it at commits
//   kinetic_coefficient   (friction laws)       the law's kinetic level of F/f_N, 1
//   slipping              (laws with a stuck state and no junctions)  1 while a block slips, else 0
//
// The names, units and docs exist here once; a reader finds them with Quantities::find_scalar or
// find_field.
#include <string_view>

#include "frictionlab/model/quantities.hpp"

namespace frictionlab::rupture_scales {

inline constexpr std::string_view drive_velocity_name = "drive_velocity";
inline constexpr std::string_view characteristic_slip_name = "characteristic_slip";
inline constexpr std::string_view kinetic_coefficient_name = "kinetic_coefficient";
inline constexpr std::string_view slipping_name = "slipping";

/// Publishes |velocity| as the drive's speed.
void publish_drive_velocity(Quantities& q, double velocity);
/// Publishes the law's characteristic slip (m), returned for a law that updates it; NaN: not yet known.
double& publish_characteristic_slip(Quantities& q, double slip);
/// Publishes the law's kinetic coefficient.
void publish_kinetic_coefficient(Quantities& q, double coefficient);
/// The field "slipping" over `node_set`, which a law with a stuck state writes (1 slipping, 0 not).
Eigen::ArrayXd& publish_slipping(Quantities& q, const std::string& node_set, Eigen::Index blocks);

/// The published value, or NaN when nothing publishes it.
double find(const Quantities& q, std::string_view name);

}  // namespace frictionlab::rupture_scales
