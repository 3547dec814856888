#include "phase_statistics.hpp"

namespace frictionlab {

namespace {
double seconds(PhaseStatistics::Clock::duration d) { return std::chrono::duration<double>(d).count(); }
double simulated_time(const PhaseStatistics& s) { return s.quiet_time + s.dynamic_time + s.creep_time; }
double wall_time(const PhaseStatistics& s) { return seconds(s.quiet_wall + s.dynamic_wall + s.creep_wall); }
}  // namespace

std::vector<std::pair<std::string, double>> PhaseStatistics::table(const EquilibriumSolver::Counts& solves,
                                                                   const CreepStepper::Counts& creep) const {
    const double total = simulated_time(*this), wall = wall_time(*this);
    return {{"quiet_fraction_of_simulated_time", total > 0 ? quiet_time / total : 0.0},
            {"quiet_fraction_of_wall_time", wall > 0 ? seconds(quiet_wall) / wall : 0.0},
            {"creep_fraction_of_simulated_time", total > 0 ? creep_time / total : 0.0},
            {"creep_fraction_of_wall_time", wall > 0 ? seconds(creep_wall) / wall : 0.0},
            {"quiet_seconds_wall", seconds(quiet_wall)},
            {"dynamic_seconds_wall", seconds(dynamic_wall)},
            {"creep_seconds_wall", seconds(creep_wall)},
            {"creep_steps", static_cast<double>(creep.steps)},
            {"quiet_steps", static_cast<double>(quiet_steps)},
            {"quiet_spans", static_cast<double>(quiet_spans)},
            {"dynamic_steps", static_cast<double>(dynamic_steps)},
            {"switches_to_quiet", static_cast<double>(switches_to_quiet)},
            {"switches_to_dynamic", static_cast<double>(switches_to_dynamic)},
            {"quiet_jumps", static_cast<double>(jumps_solved)},
            {"static_solves", static_cast<double>(solves.solves)},
            {"factorisations", static_cast<double>(solves.factorisations)}};
}

void PhaseStatistics::log_summary(spdlog::logger& log, const EquilibriumSolver::Counts& solves,
                                  const CreepStepper::Counts& creep) const {
    const double total = simulated_time(*this), wall = wall_time(*this);
    if (total > 0)
        log.info(
            "quasi_static_hybrid: quiet {:.4g} % of simulated time ({} steps), {:.4g} % of wall time; dynamic "
            "{} steps; {} switches to quiet, {} to dynamic; {} static solves, {} Newton iterations, {} "
            "factorisations",
            100 * quiet_time / total, quiet_steps, wall > 0 ? 100 * seconds(quiet_wall) / wall : 0.0, dynamic_steps,
            switches_to_quiet, switches_to_dynamic, solves.solves, solves.iterations, solves.factorisations);
    if (creep.steps > 0)
        log.info(
            "quasi_static_hybrid: creep steps {:.4g} % of simulated time ({} steps, {} Newton iterations, {} "
            "factorisations), {:.4g} % of wall time",
            100 * creep_time / total, creep.steps, creep.iterations, creep.factorisations,
            wall > 0 ? 100 * seconds(creep_wall) / wall : 0.0);
}

}  // namespace frictionlab
