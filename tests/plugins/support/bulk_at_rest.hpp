#pragma once
// A bulk model built on test-owned services, with a state vector at its reference positions, for
// tests that evaluate single effects (loaders, springs) on it.
#include "frictionlab/model/effect.hpp"
#include "plugin_test_support.hpp"

namespace frictionlab::test_support {

template <class Bulk>
struct BulkAtRest {
    explicit BulkAtRest(const typename Bulk::Params& p = {})
        : bulk(p, services.context()), layout(bulk.body().size(), bulk.body().dimension(), 0) {
        y = Eigen::VectorXd::Zero(layout.size());
        layout.positions(y) = bulk.body().reference_position.reshaped().matrix();
    }
    Context context() { return services.context(&bulk.body()); }

    Services services;
    Bulk bulk;
    StateLayout layout;
    Eigen::VectorXd y;
};

/// The forces one effect alone adds at (t, y), laid out as the positions ([fx | fz] in 2D).
inline Eigen::VectorXd forces_of_effect(Effect& e, const Eigen::VectorXd& y, const StateLayout& layout, double t) {
    Eigen::VectorXd dy = Eigen::VectorXd::Zero(layout.size());
    ForceView f = forces_of(dy, layout);
    e.add_forces(view_of(y, layout, t), f);
    return layout.velocities(dy);
}

}  // namespace frictionlab::test_support
