#pragma once
// A spring-slider's loading point for friction-law and integrator tests.
#include <string>

#include "frictionlab/model/effect.hpp"

namespace frictionlab::test_support {

/// A loading spring k (V t + d - x) on node 0: its far end moves at V from d.
class LoadPoint final : public Effect {
public:
    LoadPoint(double k, double V, double d) : k_(k), V_(V), d_(d) {}
    std::string describe() const override { return "load point"; }
    void add_forces(const StageView& s, ForceView& f) override { f.fx[0] += k_ * (V_ * s.t + d_ - s.x[0]); }

private:
    double k_, V_, d_;
};

}  // namespace frictionlab::test_support
