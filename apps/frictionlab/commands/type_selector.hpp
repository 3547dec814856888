#pragma once
// The types a `KIND[/TYPE]` argument names (list, doc, example).
#include <string>
#include <vector>

#include "frictionlab/plugins/registry.hpp"

namespace frictionlab::cli {

/// Every registered type, kind by kind.
std::vector<const TypeInfo*> all_types(const Registry& registry);

/// The types a selector names (all of them if it is empty); throws InputError with the
/// alternatives otherwise.
std::vector<const TypeInfo*> select_types(const Registry& registry, const std::string& selector);

}  // namespace frictionlab::cli
