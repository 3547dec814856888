#include "frictionlab/plugins/search.hpp"

#include <system_error>

#include "frictionlab/plugins/registry.hpp"

#ifndef FRICTIONLAB_PLUGIN_SUBDIR
#error "the build passes FRICTIONLAB_PLUGIN_SUBDIR (e.g. lib/frictionlab/plugins)"
#endif
#ifndef FRICTIONLAB_BINDIR
#error "the build passes FRICTIONLAB_BINDIR (e.g. bin)"
#endif

namespace frictionlab {

namespace {
/// `subdir` of the prefix the executable is installed in (or built in: the trees mirror each other),
/// if that directory exists.
std::optional<std::filesystem::path> under_prefix(const std::filesystem::path& executable,
                                                  const std::filesystem::path& subdir) {
    // Up from the executable's directory by as many levels as BINDIR has, to the prefix.
    auto prefix = executable.parent_path();
    for (const auto& part : std::filesystem::path(FRICTIONLAB_BINDIR))
        if (!part.empty() && part != ".") prefix = prefix.parent_path();
    auto dir = (prefix / subdir).lexically_normal();
    if (std::error_code ec; !std::filesystem::is_directory(dir, ec)) return std::nullopt;
    return dir;
}

std::optional<std::filesystem::path> running_executable() {
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return std::nullopt;
    return exe;
}
}  // namespace

std::optional<std::filesystem::path> shipped_plugin_directory(const std::filesystem::path& executable) {
    return under_prefix(executable, FRICTIONLAB_PLUGIN_SUBDIR);
}

std::optional<std::filesystem::path> shipped_plugin_directory() {
    const auto exe = running_executable();
    return exe ? shipped_plugin_directory(*exe) : std::nullopt;
}

std::optional<std::filesystem::path> shipped_directory(const std::filesystem::path& subdir) {
    const auto exe = running_executable();
    return exe ? under_prefix(*exe, subdir) : std::nullopt;
}

std::vector<std::filesystem::path> plugin_directories(const std::vector<std::filesystem::path>& command_line,
                                                      const std::vector<std::filesystem::path>& scene,
                                                      std::string_view environment,
                                                      const std::optional<std::filesystem::path>& shipped) {
    std::vector<std::filesystem::path> dirs(command_line.begin(), command_line.end());
    dirs.insert(dirs.end(), scene.begin(), scene.end());
    while (!environment.empty()) {
        const auto colon = environment.find(':');
        const auto entry = environment.substr(0, colon);
        if (!entry.empty()) dirs.emplace_back(entry);  // "a::b" and a trailing ':' are not the cwd
        environment.remove_prefix(colon == std::string_view::npos ? environment.size() : colon + 1);
    }
    if (shipped) dirs.push_back(*shipped);
    return dirs;
}

void load_plugins(Registry& registry, const std::vector<std::filesystem::path>& directories, spdlog::logger& log) {
    for (const auto& dir : directories)
        for (const auto& skipped : registry.load_directory(dir)) log.warn("{}; skipped", skipped.message);
}

}  // namespace frictionlab
