// `frictionlab doc [KIND | KIND/TYPE | TYPE]`: the reference of types and their parameters, generated
// from their declarations; `doc sweep` and `doc study`: the keys of the campaign files.
#include <iostream>

#include "../doc_writer.hpp"
#include "../type_selector.hpp"
#include "command.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/campaign/keys.hpp"
#include "frictionlab/plugins/search.hpp"
#include "frictionlab/scene/values.hpp"

namespace frictionlab::cli {

namespace {

struct DocOptions {
    std::string selector;
    std::string format = "text";
};

/// The keys of a campaign file (`which`: sweep or study), what each takes and means.
std::string campaign_doc(const std::string& which) {
    const bool sweep = which == "sweep";
    std::string out = sweep ? "sweep file (frictionlab sweep SWEEP.yaml; share/docs/scene-format.md, \"Sweeps\")\n"
                            : "accuracy study file (frictionlab study STUDY.yaml; share/docs/scene-format.md, "
                              "\"Accuracy studies\")\n";
    const auto section = [&](const std::string& title, const std::vector<ParamInfo>& params) {
        out += "\n" + title + ":\n";
        for (const auto& p : params)
            out +=
                "  " + p.key + (p.required ? " (required)" : "") + ": " + detail::expectation(p) + ". " + p.doc + "\n";
    };
    section("top-level keys", sweep ? detail::sweep_params() : detail::study_params());
    out +=
        "  seeds: a list of whole numbers >= 0, a count N (seeds 1 to N) or a range FIRST..LAST; every case runs "
        "with each. A case's runs over the seeds are its ensemble: n, mean, sd and 95 % CI of each event statistic "
        "(accuracy-standard.md). Absent: the base scene's seed only.\n";
    if (sweep) {
        out += "  grid: a mapping of key paths to lists of values; the cases take every combination.\n";
        out += "  cases: a list of cases, each times the whole grid.\n";
        section("keys of each listed case", detail::sweep_case_params());
    } else {
        out += "  reference: the converged run.\n";
        out +=
            "  half_step: optional, the reference at half its step: over seeds, its difference from the reference "
            "is the reference's own spread, which a case may differ by and still pass.\n";
        out += "  cases: the cases compared with it.\n";
        section("keys of the reference", detail::study_case_params(true));
        section("keys of each case", detail::study_case_params(false));
    }
    return out;
}

int doc(const DocOptions& o, const Invocation& in) {
    Registry registry;
    load_plugins(registry, in.global.directories({}), in.log);
    if (o.selector == "sweep" || o.selector == "study") {
        std::cout << campaign_doc(o.selector);
        return exit_code::ok;
    }
    const auto format = o.format == "md" ? DocFormat::markdown : o.format == "json" ? DocFormat::json : DocFormat::text;
    std::cout << render_doc(select_types(registry, o.selector), format);
    return exit_code::ok;
}

Execute set_up(CLI::App& cmd, GlobalOptions& global) {
    auto o = std::make_shared<DocOptions>();
    cmd.add_option("selector", o->selector,
                   "A kind (e.g. friction_law), KIND/TYPE, a type alone (three_state_junctions), or sweep or study "
                   "(their file formats); all types if omitted");
    cmd.add_option("--format", o->format, "Output format")->check(CLI::IsMember({"text", "md", "json"}));
    global.attach(cmd);
    return [o](const Invocation& in) { return doc(*o, in); };
}

}  // namespace

Command doc_command() { return {"doc", "Document types and their parameters: doc [KIND | KIND/TYPE | TYPE]", set_up}; }

}  // namespace frictionlab::cli
