#pragma once
// The types a `KIND`, `KIND/TYPE` or bare `TYPE` argument names (list, doc, example, and the
// Python module's types() and doc()).
#include <string>
#include <vector>

#include "frictionlab/plugins/registry.hpp"

namespace frictionlab::cli {

/// Every registered type, kind by kind.
std::vector<const TypeInfo*> all_types(const Registry& registry);

/// The types a selector names: all of them if it is empty, a kind's, or the one KIND/TYPE; a bare
/// name is a kind, else the type of that name of whichever kind (a name two kinds use gives both).
/// Throws InputError with the near miss, if any, and the alternatives otherwise.
std::vector<const TypeInfo*> select_types(const Registry& registry, const std::string& selector);

/// What a type is, in one line: its summary up to the first full stop, or the colon before how it
/// works (`list`, and the Python module's types()).
std::string one_line(const TypeInfo& type);

}  // namespace frictionlab::cli
