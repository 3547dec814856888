#pragma once
// What plugin unit tests need besides the plugin: the run services a constructor expects (owned
// by the test, nothing global) and a classical RK4 step over System that obeys the
// freeze-and-commit rule. The integrator plugins are tested on their own; this one is only a
// fixed reference for physics tests.
#include <memory>
#include <string>

#include <spdlog/logger.h>

#include "frictionlab/model/context.hpp"
#include "frictionlab/simulation/system.hpp"

namespace frictionlab::test_support {

struct Services {
    std::shared_ptr<spdlog::logger> log = std::make_shared<spdlog::logger>("test");  // no sinks: silent
    Quantities quantities;
    AuxAllocator aux;

    Context context(const Body* body = nullptr) { return Context{*log, 0, body, &quantities, &aux, "test"}; }
};

/// Node i's position and velocity along x in a state vector laid out as `layout` says.
inline double& x_of(Eigen::VectorXd& y, const StateLayout& layout, Index node = 0) {
    return y(layout.position_index(node, 0));
}
inline double& vx_of(Eigen::VectorXd& y, const StateLayout& layout, Index node = 0) {
    return y(layout.velocity_index(node, 0));
}

class Rk4 {
public:
    explicit Rk4(System& system)
        : system_(system),
          k1_(system.y().size()),
          k2_(k1_.size()),
          k3_(k1_.size()),
          k4_(k1_.size()),
          stage_(k1_.size()) {}

    void step(double dt) {
        const Eigen::VectorXd& y = system_.y();
        const double t = system_.time();
        system_.begin_step();
        derivative(system_, t, y, k1_);
        stage_ = y + 0.5 * dt * k1_;
        derivative(system_, t + 0.5 * dt, stage_, k2_);
        stage_ = y + 0.5 * dt * k2_;
        derivative(system_, t + 0.5 * dt, stage_, k3_);
        stage_ = y + dt * k3_;
        derivative(system_, t + dt, stage_, k4_);
        stage_ = y + dt / 6 * (k1_ + 2 * k2_ + 2 * k3_ + k4_);
        system_.accept(t + dt, stage_);
    }

private:
    System& system_;
    Eigen::VectorXd k1_, k2_, k3_, k4_, stage_;
};

}  // namespace frictionlab::test_support
