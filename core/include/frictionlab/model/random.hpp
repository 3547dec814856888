#pragma once
// Keyed random numbers (theory.md §4). A draw is a pure function of
// (scene seed, block, junction slot, purpose, draw counter), so results do not depend on thread
// count or loop order, and runs that differ only in time step draw the same junction lifetimes.
#include <cmath>
#include <cstdint>

namespace frictionlab::random {

/// What a draw is for; part of the key so different uses never share numbers.
enum class Purpose : std::uint64_t { sliding_time = 1, dislocated_time = 2, removal = 3, user = 1000 };

/// SplitMix64 finaliser: a bijective 64-bit mix with good avalanche.
constexpr std::uint64_t mix(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

struct Key {
    std::uint64_t seed = 0, block = 0, slot = 0;
    Purpose purpose = Purpose::user;
};

constexpr std::uint64_t bits(const Key& k, std::uint64_t counter) {
    std::uint64_t h = mix(k.seed);
    h = mix(h ^ k.block);
    h = mix(h ^ k.slot);
    h = mix(h ^ static_cast<std::uint64_t>(k.purpose));
    return mix(h ^ counter);
}

/// Uniform in the open interval (0, 1).
constexpr double uniform(const Key& k, std::uint64_t counter) {
    return (static_cast<double>(bits(k, counter) >> 11) + 0.5) * 0x1.0p-53;
}

/// Standard normal (Box–Muller on two keyed uniforms).
inline double normal(const Key& k, std::uint64_t counter) {
    const double u1 = uniform(k, 2 * counter), u2 = uniform(k, 2 * counter + 1);
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.14159265358979323846 * u2);
}

/// N(mean, sd) truncated to values > lower, by rejection (theory.md B.14): correctly normalised,
/// no point mass. `counter` advances by the number of draws used, so the next call draws afresh.
inline double truncated_normal(const Key& k, std::uint64_t& counter, double mean, double sd, double lower) {
    for (;;) {
        const double t = mean + sd * normal(k, counter++);
        if (t > lower) return t;
    }
}

}  // namespace frictionlab::random
