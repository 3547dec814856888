#pragma once
// What a component's constructor receives besides its Params: the run's services. Nothing here is
// global; a test builds its own Context.
#include <cstdint>
#include <string>

#include <spdlog/logger.h>

#include "frictionlab/model/body.hpp"
#include "frictionlab/model/quantities.hpp"
#include "frictionlab/model/resolved_choice.hpp"

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
    /// Where the run records the values components choose for keys left `auto` (null: nowhere, as
    /// in a test that builds a component alone).
    ResolvedChoices* resolved_choices = nullptr;
    /// An effect of the scene was refused (the scene is refused with it): what it would publish is
    /// missing, so a component built after it does not refuse for want of it (no knock-on error).
    bool effects_refused = false;

    /// Records that this component chose `value` for its `key` (resolved_choice.hpp), and why.
    void resolved(const std::string& key, std::string value, std::string reason) const {
        if (resolved_choices)
            resolved_choices->push_back({name.empty() ? key : name + "." + key, std::move(value), std::move(reason)});
    }
};

}  // namespace frictionlab
