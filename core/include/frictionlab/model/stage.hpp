#pragma once
#include <string>

namespace frictionlab {

/// One phase of a run (e.g. "settle" with the normal load only, then "load"), as effects see it.
struct StageInfo {
    std::string name;
    int index = 0;
    double t_start = 0;   // s, simulated time at the start of the stage
    double duration = 0;  // s
    /// False while settling: friction laws keep their discrete state (no breaking), theory.md B.18.
    bool friction_events = true;
};

}  // namespace frictionlab
