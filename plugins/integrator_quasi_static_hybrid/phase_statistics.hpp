#pragma once
// Where a hybrid run's steps and time go, phase by phase (quiet, dynamic, creep): run.yaml's
// integrator_statistics and the run's closing log lines. The static solves and the creep steps are
// counted where they are made (EquilibriumSolver, CreepStepper) and passed in.
#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include <spdlog/logger.h>

#include "creep_stepper.hpp"
#include "equilibrium_solver.hpp"

namespace frictionlab {

struct PhaseStatistics {
    using Clock = std::chrono::steady_clock;

    long long quiet_steps = 0, quiet_spans = 0, jumps_solved = 0, dynamic_steps = 0;
    long long switches_to_quiet = 0, switches_to_dynamic = 0;
    double quiet_time = 0, dynamic_time = 0, creep_time = 0;  // simulated, s
    Clock::duration quiet_wall{}, dynamic_wall{}, creep_wall{};

    /// run.yaml's integrator_statistics.
    std::vector<std::pair<std::string, double>> table(const EquilibriumSolver::Counts& solves,
                                                      const CreepStepper::Counts& creep) const;
    /// The same, for the log at the end of the run.
    void log_summary(spdlog::logger& log, const EquilibriumSolver::Counts& solves,
                     const CreepStepper::Counts& creep) const;

    template <class Archive>
    void serialize(Archive& ar) {
        auto quiet = quiet_wall.count(), dynamic = dynamic_wall.count(), creeping = creep_wall.count();
        ar(quiet_steps, quiet_spans, jumps_solved, dynamic_steps, switches_to_quiet, switches_to_dynamic, quiet_time,
           dynamic_time, creep_time, quiet, dynamic, creeping);
        quiet_wall = Clock::duration(quiet), dynamic_wall = Clock::duration(dynamic);
        creep_wall = Clock::duration(creeping);
    }
};

}  // namespace frictionlab
