#pragma once
// Drives a StickSlipLaw (coulomb, slip_weakening) as an integrator would, on a hand-made body whose
// interface nodes start at x = 0. The test writes the normal force and chooses each end-of-step
// position and velocity; with k_t a power of two, thresholds and positions are exact.
#include <memory>
#include <vector>

#include "frictionlab/model/body.hpp"
#include "frictionlab/model/stage.hpp"
#include "frictionlab/model/state.hpp"

#include "plugin_test_support.hpp"
#include "stick_slip_law.hpp"

namespace frictionlab::testing {

inline constexpr double exact_stiffness = 1024;  // N/m
inline constexpr double exact_normal = 8;        // N
inline constexpr double exact_dt = 0x1p-16;      // s

template <class Law>
struct StickSlipRig {
    explicit StickSlipRig(const typename Law::Params& params, Index blocks = 2) {
        body.reference_position =
            planar_positions(Eigen::ArrayXd::Zero(blocks), Eigen::ArrayXd::LinSpaced(blocks, 0, 1));
        body.mass = Eigen::ArrayXd::Ones(blocks);
        NodeSet interface;
        for (Index i = 0; i < blocks; ++i) interface.push_back(i);
        body.node_sets["interface"] = interface;
        normal = &services.quantities.field("normal_force", "interface", blocks, "N", "test");
        layout = StateLayout(blocks, 2, 0);
        y = Eigen::VectorXd::Zero(layout.size());
        law = std::make_unique<Law>(params, services.context(&body));
    }

    StageView view() const { return view_of(y, layout, t); }
    double x(Index i) const { return y[layout.position_index(i, 0)]; }
    double v(Index i) const { return y[layout.velocity_index(i, 0)]; }
    const stick_slip::Block<1>& block(Index i) const { return law->template block<1>(i); }
    stick_slip::Mode mode(Index i) const { return law->mode(i); }

    void stage(bool friction_events) {
        StageInfo info{friction_events ? "load" : "settle", stage_index++, t, 1.0, friction_events};
        law->begin_stage(info, view());
    }
    /// One accepted step that brings block i to position xi and velocity vi.
    void move(Index i, double xi, double vi) {
        law->begin_step(view());
        y[layout.position_index(i, 0)] = xi;
        y[layout.velocity_index(i, 0)] = vi;
        t += exact_dt;
        law->commit(view(), exact_dt);
    }
    /// Normal force on every block, in contact from the next commit (one step at rest).
    void press(double f_n) {
        normal->setConstant(f_n);
        move(0, x(0), v(0));
    }

    /// x-force on block i at the current state.
    double force(Index i) {
        Eigen::VectorXd dy = Eigen::VectorXd::Zero(layout.size());
        ForceView f = forces_of(dy, layout);
        law->add_forces(view(), f);
        return f.fx[i];
    }
    /// x-force on block i at a stage (x, v), states frozen.
    double stage_force(Index i, double xi, double vi) {
        const Eigen::VectorXd saved = y;
        y[layout.position_index(i, 0)] = xi;
        y[layout.velocity_index(i, 0)] = vi;
        const double f = force(i);
        y = saved;
        return f;
    }
    double energy_at(Index i, double xi) {
        const Eigen::VectorXd saved = y;
        y[layout.position_index(i, 0)] = xi;
        const double e = law->potential_energy(view());
        y = saved;
        return e;
    }

    test_support::Services services;
    Body body;
    Eigen::ArrayXd* normal = nullptr;
    StateLayout layout;
    Eigen::VectorXd y;
    double t = 0;
    int stage_index = 0;
    std::unique_ptr<Law> law;
};

}  // namespace frictionlab::testing
