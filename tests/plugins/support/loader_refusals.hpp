#pragma once
// Loaders on a 3D lattice of 2.5 mm blocks, bounded or periodic across its width, and what a
// loader's set-up refuses on it (tests of loaders over faces and patches).
#include <string>

#include "bulk_at_rest.hpp"
#include "frictionlab/base/errors.hpp"
#include "spring_lattice_2d.hpp"
#include "spring_lattice_3d.hpp"

namespace frictionlab::test_support {

/// 41 x ny x 9 blocks at 2.5 mm.
inline SpringLattice3d::Params lattice_across(int ny,
                                              SpringLattice3d::Across across = SpringLattice3d::Across::bounded) {
    SpringLattice3d::Params p;
    p.ny = ny;
    p.across = across;
    p.width = across == SpringLattice3d::Across::bounded ? (ny - 1) * 2.5e-3 : ny * 2.5e-3;
    return p;
}

/// The InputError a Loader built with p meets on lattice_across(ny, across), or on the default 2D
/// lattice when ny is 0; "" if it builds.
template <class Loader>
std::string refusal_on_lattice(int ny, const typename Loader::Params& p,
                               SpringLattice3d::Across across = SpringLattice3d::Across::bounded) {
    try {
        if (ny == 0) {
            BulkAtRest<SpringLattice2d> s;
            Loader loader(p, s.context());
        } else {
            BulkAtRest<SpringLattice3d> s(lattice_across(ny, across));
            Loader loader(p, s.context());
        }
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace frictionlab::test_support
