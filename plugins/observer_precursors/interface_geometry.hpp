#pragma once
// The interface as the rupture detector sees it, from the body: a line of blocks, or a 2D grid.
#include "frictionlab/model/body.hpp"
#include "rupture_event_detector.hpp"

namespace frictionlab {

/// The blocks of `interface` (the node set, in its order): positions along x from the trailing edge
/// and the length L; on a 3D body besides, positions across from the first side face, the width B,
/// and each block's neighbours, the blocks of the grid within one spacing along and across (a width
/// periodic across, B = ny l_s, joins its two sides). On a 2D body the set is a line in x order.
RuptureEventDetector::Interface interface_geometry(const Body& body, const NodeSet& interface);

}  // namespace frictionlab
