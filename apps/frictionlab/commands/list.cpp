// `frictionlab list`: every kind and type, with the library that provides it and what it is, in a line.
#include <iostream>

#include "../type_selector.hpp"
#include "command.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/plugins/search.hpp"

namespace frictionlab::cli {

namespace {

int list(const Invocation& in) {
    Registry registry;
    load_plugins(registry, in.global.directories({}), in.log);
    for (const auto* t : all_types(registry))
        std::cout << to_string(t->kind) << "/" << t->type << "  " << (t->library.empty() ? "built in" : t->library)
                  << "\n    " << one_line(*t) << "\n";
    return exit_code::ok;
}

Execute set_up(CLI::App& cmd, GlobalOptions& global) {
    global.attach(cmd);
    return list;
}

}  // namespace

Command list_command() {
    return {"list", "List every kind and type, with the library that provides it and what it is", set_up};
}

}  // namespace frictionlab::cli
