#include "frictionlab/campaign/sweep_tables.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "frictionlab/campaign/case_outputs.hpp"
#include "frictionlab/campaign/csv_cell.hpp"
#include "frictionlab/output/csv_columns.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/output/atomic_file.hpp"

namespace frictionlab {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

std::string number(double v) { return std::isnan(v) ? "nan" : fmt::format("{:.10g}", v); }

/// What a case's rupture outputs say: its events and the figures of its row.
struct CaseEvents {
    CsvColumns events;
    std::size_t count = 0, precursors = 0;
    double global_static_coefficient = nan;
    double first_precursor_ratio = nan;  // F_S/F_N at the start of the first precursor
};

CaseEvents read_events(const CampaignRun& c) {
    CaseEvents out;
    const auto files = rupture_files(c.scene);
    if (!files) return out;
    out.events = read_csv_columns(files->events);
    out.count = out.events["t_start"].size();
    const auto& global = out.events["global"];
    const auto& ratio = out.events["force_ratio"];
    const auto& start = out.events["t_start"];
    double first = std::numeric_limits<double>::infinity();
    for (std::size_t e = 0; e < out.count; ++e) {
        if (global.size() > e && global[e] > 0.5) continue;
        ++out.precursors;
        if (start[e] < first && ratio.size() > e) {
            first = start[e];
            out.first_precursor_ratio = ratio[e];
        }
    }
    try {
        if (std::filesystem::exists(files->summary)) {
            const YAML::Node n = YAML::LoadFile(files->summary.string())["global_static_coefficient"];
            if (n && n.IsScalar() && n.Scalar() != "null") out.global_static_coefficient = n.as<double>();
        }
    } catch (const YAML::Exception&) {
        // A summary that cannot be read leaves the coefficient unknown (nan), as a run without global slip.
    }
    return out;
}

}  // namespace

void write_sweep_tables(const Sweep& sweep, const std::vector<CampaignRun>& runs,
                        const std::vector<CaseRecord>& records, const std::filesystem::path& output) {
    std::vector<std::string> columns;  // the varied values, in order of first use
    for (const auto& c : runs)
        for (const auto& [key, value] : c.values)
            if (std::find(columns.begin(), columns.end(), key) == columns.end()) columns.push_back(key);
    const auto values_of = [&](const CampaignRun& c) {
        std::string text;
        for (const auto& key : columns) {
            const auto it =
                std::find_if(c.values.begin(), c.values.end(), [&](const auto& v) { return v.first == key; });
            text += fmt::format(",{}", csv_cell(it == c.values.end() ? std::string() : it->second));
        }
        return text;
    };
    std::string header = "case";
    // fmt, not "," + a temporary string: GCC 12 reports a false -Wrestrict on that.
    for (const auto& key : columns) header += fmt::format(",{}", csv_cell(key));

    const std::string comment =
        fmt::format("# frictionlab sweep {}{}: each case's run.yaml in cases/ records its resolved scene\n",
                    sweep.file.filename().string(), sweep.title.empty() ? "" : " (" + sweep.title + ")");
    std::string table = comment + header +
                        ",status,reason,scene_hash,global_static_coefficient,events,precursor_count,"
                        "first_precursor_force_ratio,steps,wall_seconds,cpu_seconds\n";
    std::string events = comment + header + ",event,t_start,t_end,force_ratio,extent_over_length,kind\n";
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const auto& c = runs[i];
        const auto& r = records.at(i);
        const CaseEvents e = r.status == "done" ? read_events(c) : CaseEvents{};
        table += fmt::format("{}{},{},{},{},{},{},{},{},{},{:.4g},{:.4g}\n", c.name, values_of(c), r.status,
                             csv_cell(r.reason), r.scene_hash, number(e.global_static_coefficient), e.count,
                             e.precursors, number(e.first_precursor_ratio), r.summary.steps, r.summary.wall_seconds,
                             r.summary.cpu_seconds);
        auto column = [&](const char* name, std::size_t k) {
            const auto it = e.events.find(name);
            return it == e.events.end() || k >= it->second.size() ? nan : it->second[k];
        };
        for (std::size_t k = 0; k < e.count; ++k)
            events += fmt::format("{}{},{},{},{},{},{},{}\n", c.name, values_of(c), number(column("event", k)),
                                  number(column("t_start", k)), number(column("t_end", k)),
                                  number(column("force_ratio", k)), number(column("extent_over_length", k)),
                                  column("global", k) > 0.5 ? "global" : "precursor");
    }
    write_file_atomically(output / "sweep.csv", table);
    write_file_atomically(output / "events.csv", events);
}

}  // namespace frictionlab
