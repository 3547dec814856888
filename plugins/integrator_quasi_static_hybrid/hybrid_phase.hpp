#pragma once
// The hybrid's phase (share/docs/quasi-static.md): which kind of step it takes now, and what one
// quiet step hands to the next.
#include <Eigen/Core>

namespace frictionlab {

struct HybridPhase {
    bool quiet = false;            // quiet steps (equilibrium solves), else dynamic ones
    bool creeping = false;         // dynamic, below creep_speed (with the hysteresis): creep steps
    bool projected = false;        // `forming` holds the quasi-static state the first quiet step starts from
    Eigen::VectorXd forming;       // the quiet solution being formed
    int short_steps = 0;           // quiet steps in a row shorter than dt
    const char* why_dynamic = "";  // why the last quiet step was refused, for the log

    template <class Archive>
    void serialize(Archive& ar) {
        ar(quiet, creeping, projected, forming, short_steps);  // the order checkpoints have always had
    }
};

}  // namespace frictionlab
