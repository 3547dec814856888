#pragma once
// A value a component settles itself at assembly for a key the scene leaves to it (`auto`): the
// precursors observer's criterion is pinned_fraction where the friction law publishes junction
// counts and slip otherwise. The scene keeps saying `auto` (its hash stays that of what the user
// wrote); run.yaml records what it became under `resolved_choices`, and `check` prints it.
#include <string>
#include <vector>

namespace frictionlab {

struct ResolvedChoice {
    std::string key_path;  // where the scene leaves the choice, e.g. "observers[1].criterion"
    std::string value;     // as the scene would write it, e.g. "slip"
    std::string reason;    // e.g. "no effect of this scene publishes junction counts"
};

using ResolvedChoices = std::vector<ResolvedChoice>;

}  // namespace frictionlab
