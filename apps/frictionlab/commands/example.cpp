// `frictionlab example [KIND/]TYPE`: a valid YAML snippet of a type with every default.
#include <iostream>

#include <fmt/format.h>

#include "../type_selector.hpp"
#include "command.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/plugins/search.hpp"
#include "frictionlab/scene/scene.hpp"

namespace frictionlab::cli {

namespace {

struct ExampleOptions {
    std::string selector;
};

int example(const ExampleOptions& o, const Invocation& in) {
    Registry registry;
    load_plugins(registry, in.global.directories({}), in.log);
    const auto types = select_types(registry, o.selector);
    if (types.size() != 1)
        throw InputError(
            fmt::format("'{}' names {} types; example needs one: TYPE or KIND/TYPE, e.g. "
                        "three_state_junctions or friction_law/three_state_junctions",
                        o.selector, types.size()));
    std::cout << example_yaml(*types.front());
    return exit_code::ok;
}

Execute set_up(CLI::App& cmd, GlobalOptions& global) {
    auto o = std::make_shared<ExampleOptions>();
    cmd.add_option("selector", o->selector, "TYPE or KIND/TYPE, e.g. coulomb or friction_law/coulomb")->required();
    global.attach(cmd);
    return [o](const Invocation& in) { return example(*o, in); };
}

}  // namespace

Command example_command() {
    return {"example", "Print a valid YAML snippet with every default: example [KIND/]TYPE", set_up};
}

}  // namespace frictionlab::cli
