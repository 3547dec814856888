#include "python_module.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>

#include "command.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/plugins/search.hpp"

namespace frictionlab::cli {

std::vector<std::string> python_module_command_line(const std::string& module,
                                                    const std::vector<std::string>& arguments) {
    std::string relative = module;  // frictionlab.plot: frictionlab/plot
    std::replace(relative.begin(), relative.end(), '.', '/');
    std::optional<std::filesystem::path> package;
    for (const char* subdir : {FRICTIONLAB_PYTHON_INSTALL_SUBDIR, FRICTIONLAB_PYTHON_BUILD_SUBDIR}) {
        const auto dir = shipped_directory(subdir);
        if (dir && std::filesystem::exists(*dir / relative)) {
            package = dir;
            break;
        }
    }
    if (!package)
        throw InputError("cannot find the Python package " + module +
                         " in " FRICTIONLAB_PYTHON_INSTALL_SUBDIR " or " FRICTIONLAB_PYTHON_BUILD_SUBDIR
                         " next to this frictionlab");
    const char* path = std::getenv("PYTHONPATH");
    setenv("PYTHONPATH", (package->string() + (path && *path ? ":" + std::string(path) : "")).c_str(), 1);
    const char* env = std::getenv("FRICTIONLAB_PYTHON");
    const std::string python = env ? env : std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    std::vector<std::string> args{python, "-m", module};
    args.insert(args.end(), arguments.begin(), arguments.end());
    return args;
}

void exec(std::vector<std::string> args) {
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    std::fprintf(stderr, "cannot run %s: %s\n", argv[0], std::strerror(errno));
    std::_Exit(exit_code::run_failure);
}

}  // namespace frictionlab::cli
