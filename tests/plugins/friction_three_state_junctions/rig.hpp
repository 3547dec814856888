#pragma once
// Drives a ThreeStateJunctions law as an integrator would, on a hand-made body whose interface
// nodes all start at x = 0 (so that dyadic displacements give exact forces): in 2D, or in 3D with
// the blocks along y (the interface plane (x, y)). The test writes the normal force and chooses each
// end-of-step position.
#include <memory>
#include <vector>

#include <spdlog/logger.h>

#include "frictionlab/model/body.hpp"
#include "frictionlab/model/context.hpp"
#include "frictionlab/model/quantities.hpp"
#include "frictionlab/model/stage.hpp"
#include "frictionlab/model/state.hpp"

#include "three_state_junctions.hpp"

namespace frictionlab::testing {

/// Exact-arithmetic parameters: k_s = 2^10 N/m, deterministic lifetimes t_s = 2^-12 s,
/// t_d = 2^-10 s, so positions, forces and deadlines are exact binary fractions where they can be.
inline ThreeStateJunctions::Params exact_params() {
    ThreeStateJunctions::Params p;
    p.tangential_stiffness = 1024;
    p.sliding_time_mean = 0x1p-12;
    p.sliding_time_sd = 0;
    p.dislocated_time_mean = 0x1p-10;
    p.dislocated_time_sd = 0;
    return p;
}

inline constexpr double exact_dt = 0x1p-16;

struct Rig {
    explicit Rig(const ThreeStateJunctions::Params& params, Index blocks = 3, std::uint64_t seed = 1, double x0 = 0,
                 int dimension = 2)
        : log("three_state_junctions_test") {
        const Eigen::ArrayXd along = Eigen::ArrayXd::LinSpaced(blocks, 0, 1);
        if (dimension == 2) {
            body.reference_position = planar_positions(Eigen::ArrayXd::Constant(blocks, x0), along);
        } else {
            body.reference_position = Eigen::ArrayXXd::Zero(blocks, 3);
            body.reference_position.col(0) = x0;
            body.reference_position.col(1) = along;
            body.contact_frame = ContactFrame::horizontal_base(3);
        }
        body.mass = Eigen::ArrayXd::Ones(blocks);
        NodeSet interface;
        for (Index i = 0; i < blocks; ++i) interface.push_back(i);
        body.node_sets["interface"] = interface;
        normal = &quantities.field("normal_force", "interface", blocks, "N", "test");
        layout = StateLayout(blocks, dimension, 0);
        y = Eigen::VectorXd::Zero(layout.size());
        for (int axis = 0; axis < dimension; ++axis)
            layout.positions_along(y, axis) = body.reference_position.col(axis).matrix();
        Context ctx{log, seed, &body, &quantities, nullptr, "friction"};
        law = std::make_unique<ThreeStateJunctions>(params, ctx);
        p = law->junction_load();
        k = law->junction_stiffness();
    }

    StageView view() const { return view_of(y, layout, t); }
    double x(Index i) const { return y[layout.position_index(i, 0)]; }
    const BlockJunctions& block(Index i) const { return law->block(i); }
    const PlanarJunctions& planar_block(Index i) const { return law->planar_block(i); }

    void stage(bool friction_events) {
        StageInfo info{friction_events ? "load" : "settle", stage_index++, t, 1.0, friction_events};
        law->begin_stage(info, view());
    }

    /// One accepted step to positions x (one per block) and normal forces P.
    void step(const std::vector<double>& xs, double dt = exact_dt) {
        law->begin_step(view());
        for (std::size_t i = 0; i < xs.size(); ++i) y[layout.position_index(static_cast<Index>(i), 0)] = xs[i];
        t += dt;
        law->commit(view(), dt);
    }
    /// One accepted step that moves block i only.
    void move(Index i, double xi, double dt = exact_dt) {
        const auto positions = layout.positions_along(y, 0);
        std::vector<double> xs(positions.begin(), positions.end());
        xs[static_cast<std::size_t>(i)] = xi;
        step(xs, dt);
    }
    void hold(int steps, double dt = exact_dt) {
        for (int n = 0; n < steps; ++n) move(0, x(0), dt);
    }

    /// x-force on block i from the law at the current state.
    double force(Index i) { return forces()[static_cast<std::size_t>(i)]; }
    std::vector<double> forces() {
        Eigen::VectorXd dy = Eigen::VectorXd::Zero(layout.size());
        ForceView f = forces_of(dy, layout);
        law->add_forces(view(), f);
        return {f.fx.data(), f.fx.data() + layout.nodes};
    }
    /// In 3D: one accepted step that moves block i by `by` in the interface plane from its reference.
    void move_in_plane(Index i, const Eigen::Vector2d& by) {
        law->begin_step(view());
        for (int axis = 0; axis < 2; ++axis)
            y[layout.position_index(i, axis)] = body.reference_position(i, axis) + by[axis];
        t += exact_dt;
        law->commit(view(), exact_dt);
    }
    /// In 3D: the in-plane force on block i from the law now.
    Eigen::Vector2d plane_force(Index i) {
        Eigen::VectorXd dy = Eigen::VectorXd::Zero(layout.size());
        ForceView f = forces_of(dy, layout);
        law->add_forces(view(), f);
        return {f.forces_along(0)(i), f.forces_along(1)(i)};
    }
    /// x-force on block i at a stage position, without accepting a step.
    double stage_force(Index i, double xi) {
        double& x = y[layout.position_index(i, 0)];
        const double saved = x;
        x = xi;
        const double f = force(i);
        x = saved;
        return f;
    }

    spdlog::logger log;
    Body body;
    Quantities quantities;
    Eigen::ArrayXd* normal = nullptr;
    StateLayout layout;
    Eigen::VectorXd y;
    double t = 0;
    int stage_index = 0;
    std::unique_ptr<ThreeStateJunctions> law;
    double p = 0, k = 0;
};

}  // namespace frictionlab::testing
