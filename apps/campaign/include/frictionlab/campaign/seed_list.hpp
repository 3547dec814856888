#pragma once
// The `seeds:` list of a campaign file (a sweep's or a study's): whole numbers >= 0, each error
// at its line and column.
#include <cstdint>
#include <vector>

#include "frictionlab/scene/values.hpp"
#include "frictionlab/scene/yaml.hpp"

namespace frictionlab::detail {

std::vector<std::int64_t> read_seed_list(const Entry& entry, Reporter& reporter);

}  // namespace frictionlab::detail
