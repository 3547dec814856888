#include "frictionlab/campaign/seed_list.hpp"

#include <cmath>

namespace frictionlab::detail {

std::vector<std::int64_t> read_seed_list(const Entry& entry, Reporter& reporter) {
    std::vector<std::int64_t> seeds;
    for (std::size_t i = 0; i < entry.value.size(); ++i) {
        const double seed = entry.value[i].as<double>();
        // Above 2^53 a double no longer holds every whole number.
        if (seed < 0 || seed != std::floor(seed) || seed > 9.0e15) {
            reporter.error(entry.value[i], index_path("seeds", i),
                           "expected a whole number >= 0, got " + quote(entry.value[i].Scalar()));
            continue;
        }
        seeds.push_back(static_cast<std::int64_t>(seed));
    }
    if (seeds.empty() && entry.value.size() == 0)
        reporter.error(entry.site(), "seeds", "expected a non-empty list of seeds, got an empty list");
    return seeds;
}

}  // namespace frictionlab::detail
