#pragma once
// What a component's constructor receives besides its Params: the run's services. Nothing here is
// global; a test builds its own Context.
#include <cstdint>
#include <string>

#include <spdlog/logger.h>

#include "frictionlab/model/body.hpp"
#include "frictionlab/model/quantities.hpp"

namespace frictionlab {

class Registry;

/// Slices of the aux part of the state vector, handed out to effects at construction.
struct AuxAllocator {
    Index count = 0;
    Index allocate(Index n) {
        const Index first = count;
        count += n;
        return first;
    }
};

struct Context {
    spdlog::logger& log;
    std::uint64_t seed = 0;      // the scene seed; draws are keyed on it (random.hpp)
    const Body* body = nullptr;  // null only while the bulk model itself is being built
    Quantities* quantities = nullptr;
    AuxAllocator* aux = nullptr;
    std::string name;  // where the component stands in the scene, e.g. "loaders[1]"
    /// The run's types, for a component that builds another by its type name as a scene would
    /// (the quasi-static stepper's dynamic scheme) instead of linking another plugin's code.
    const Registry* registry = nullptr;
};

}  // namespace frictionlab
