#pragma once
// How large a body may be: every bulk model refuses, from its parameters alone, a node count whose
// memory would exceed what a run may take before its first step, so that such a scene is refused at
// its key in no time instead of running out of memory minutes later with no key named.
#include <string>
#include <string_view>

namespace frictionlab {

/// The memory a body may take before the first step: 4 Mi nodes of the 2D lattice (430 bytes each).
inline constexpr double largest_body_bytes = 4.0 * 1024 * 1024 * 430;

/// Why a body of `nodes` nodes of `bytes_per_node` each (measured for the model) is too large, or
/// "". `count` is how the scene sets the count ("nx x nz"), `body` what the model builds ("lattice").
std::string body_too_large(double nodes, double bytes_per_node, std::string_view count, std::string_view body);

}  // namespace frictionlab
