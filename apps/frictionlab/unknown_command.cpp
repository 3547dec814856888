#include "unknown_command.hpp"

#include <algorithm>
#include <vector>

#include "frictionlab/base/diagnostics.hpp"

namespace frictionlab::cli {

std::string unknown_command(const CLI::App& app, int argc, char** argv) {
    std::vector<std::string> names;
    for (const auto* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
    for (int i = 1; i < argc; ++i) {
        const std::string word = argv[i];
        if (word == "--log-level" || word == "--plugin-path") {
            ++i;  // its value
            continue;
        }
        if (word.starts_with("-")) continue;
        if (std::find(names.begin(), names.end(), word) != names.end()) return "";
        const std::string guess = did_you_mean(word, names);
        std::string known;
        for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
        return "unknown command '" + word + "'" + (guess.empty() ? "" : "; did you mean '" + guess + "'?") +
               " (commands: " + known + ")";
    }
    return "";
}

}  // namespace frictionlab::cli
