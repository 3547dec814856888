#pragma once
// Durations of the sliding and dislocated states, t_s and t_d (Li et al. 2020, Eq. 12): Gaussian
// truncated to t > 0 by rejection, so the density is renormalised and has no point mass (theory.md
// B.14).
//
// A draw is keyed on (seed, block, junction id, purpose, the junction's own draw count), so a
// junction draws the same lifetimes whatever the loop order or the time step. The lower bound is 0,
// not dt, for that same reason: the state machine judges a deadline at the end of a step, so a
// junction stays in a state for at least one step anyway, which is B.14's t >= dt.
#include <cstdint>

namespace frictionlab {

class LifetimeSampler {
public:
    struct Gaussian {
        double mean = 0, sd = 0;
    };

    LifetimeSampler(std::uint64_t seed, Gaussian sliding, Gaussian dislocated)
        : seed_(seed), sliding_(sliding), dislocated_(dislocated) {}

    /// t_s for junction `id` of `block`; advances `counter` by the draws used.
    double sliding(std::uint64_t block, std::uint64_t id, std::uint64_t& counter) const;
    /// t_d for junction `id` of `block`; advances `counter` by the draws used.
    double dislocated(std::uint64_t block, std::uint64_t id, std::uint64_t& counter) const;

private:
    std::uint64_t seed_;
    Gaussian sliding_, dislocated_;
};

}  // namespace frictionlab
