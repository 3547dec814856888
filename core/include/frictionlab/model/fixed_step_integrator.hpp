#pragma once
// What every fixed-step integrator shares: its one parameter, the step dt, declared once.
#include <string>

#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"

namespace frictionlab {

struct FixedStepParams {
    double dt = 2e-7;  // Li et al. (2020) §3.1
};

class FixedStepIntegrator : public Integrator {
public:
    bool checkpointable() const override { return true; }  // its scratch arrays are refilled every step
    using Params = FixedStepParams;
    double nominal_dt() const override { return dt_; }

protected:
    // The checks every scheme's spec() makes (fixed_step_spec), for Params built in code too.
    explicit FixedStepIntegrator(const Params& p) : dt_(fixed_step_spec({}).checked(p).dt) {}
    /// The spec of a fixed-step scheme: `summary` describes it, the key is dt.
    static ParamSpec<Params> fixed_step_spec(std::string summary) {
        ParamSpec<Params> s(std::move(summary));
        s.add("dt", &Params::dt, "Time step.").unit("s").greater_than(0);
        s.dimensions({2, 3});  // it steps the state as laid out, whatever the body's dimension
        return s;
    }
    double dt_;
};

}  // namespace frictionlab
