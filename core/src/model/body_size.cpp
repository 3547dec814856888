#include "frictionlab/model/body_size.hpp"

#include <cmath>

#include <fmt/format.h>

namespace frictionlab {

std::string body_too_large(double nodes, double bytes_per_node, std::string_view count, std::string_view body) {
    const double most_nodes = std::floor(largest_body_bytes / bytes_per_node);
    if (nodes <= most_nodes) return {};
    return fmt::format(
        "{} = {:.0f} nodes would need about {:.3g} GB of memory before the first step; a {} may have at most {:.0f} "
        "nodes",
        count, nodes, nodes * bytes_per_node / 1e9, body, most_nodes);
}

}  // namespace frictionlab
