// `frictionlab check FILE`: validates a scene (and estimates its stable time step), a study or a
// sweep, reporting every error with file:line:column.
#include <iostream>

#include "command.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/campaign/file_kind.hpp"
#include "frictionlab/simulation/run.hpp"
#include "frictionlab/simulation/stage_start_check.hpp"
#include "run_flags.hpp"
#include "scene_input.hpp"
#include "study.hpp"
#include "sweep.hpp"

namespace frictionlab::cli {

namespace {

struct CheckOptions {
    std::filesystem::path file;
    std::vector<std::string> overrides;
    OutputOption output;
};

int check(CheckOptions o, const Invocation& in) {
    if (o.output.refuse_empty(in.log)) return exit_code::bad_input;
    switch (campaign_file_kind(o.file)) {
        case CampaignFileKind::study:
            return check_study(o.file, o.output.directory, in);
        case CampaignFileKind::sweep:
            return check_sweep(o.file, o.output.directory, in);
        case CampaignFileKind::scene:
            break;
    }
    Registry registry;
    if (!o.output.directory.empty()) o.overrides.push_back("output=" + o.output.directory);
    const auto scene = read_scene(o.file, o.overrides, in.global, registry);
    if (!scene) return exit_code::bad_input;
    const RunInfo built = check_scene_builds(*scene, registry, *in.global.checking_logger());
    Diagnostics diagnostics;
    std::vector<std::string> stable_steps;
    check_stage_starts(*scene, registry, *in.global.checking_logger(), diagnostics, &stable_steps);
    if (!diagnostics.empty()) return report_errors(diagnostics, o.file);
    std::cout << o.file.string() << ": ok\n";
    for (const auto& line : stable_steps) std::cout << "  " << line << "\n";
    for (const auto& c : built.resolved_choices)
        std::cout << "  " << c.key_path << ": auto is " << c.value << " (" << c.reason << ")\n";
    for (const auto& caveat : built.caveats) std::cout << "  warning: " << caveat << "\n";
    return exit_code::ok;
}

Execute set_up(CLI::App& cmd, GlobalOptions& global) {
    auto o = std::make_shared<CheckOptions>();
    cmd.add_option("scene", o->file, "Scene, study or sweep file (YAML)")->required();
    cmd.add_option("--set", o->overrides, "Override a scene value: key.path=value (repeatable)");
    o->output.add(cmd, "Output directory (overrides the scene's `output:`)");
    global.attach(cmd);
    return [o](const Invocation& in) { return check(*o, in); };
}

}  // namespace

Command check_command() {
    return {"check",
            "Validate a scene (and estimate its stable time step), study or sweep; report every error with "
            "file:line:column",
            set_up};
}

}  // namespace frictionlab::cli
