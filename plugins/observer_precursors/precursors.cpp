#include "precursors.hpp"

#include <fstream>
#include <limits>

#include <fmt/format.h>

#include "frictionlab/output/atomic_file.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/output/provenance.hpp"
#include "frictionlab/output/output_file_name.hpp"

namespace frictionlab {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// YAML 1.2 reads a JSON number; NaN (unknown yet) is written as null.
std::string yaml_number(double v) { return std::isfinite(v) ? fmt::format("{:.10g}", v) : "null"; }

const std::vector<std::string> event_columns{"event",
                                             "finished",
                                             "t_start",
                                             "t_end",
                                             "duration",
                                             "driving_force",
                                             "normal_load",
                                             "force_ratio",
                                             "nucleation_block",
                                             "nucleation_x",
                                             "extent",
                                             "extent_over_length",
                                             "min_ruptured_x",
                                             "max_ruptured_x",
                                             "ruptured_blocks",
                                             "global",
                                             "front_speed",
                                             "crossing_speed",
                                             "max_slip",
                                             "out_of_contact",
                                             "front_speed_error",
                                             "crossing_speed_error"};
const std::vector<std::string> front_columns{"event", "block", "x", "distance", "time", "delay", "resolution"};
const std::vector<std::string> contact_columns{"time", "block", "x", "in_contact"};
const ColumnTypes event_types{{"event", "nucleation_block", "ruptured_blocks", "out_of_contact"},
                              {"finished", "global"},
                              {{"event", "1"},
                               {"finished", "1"},
                               {"t_start", "s"},
                               {"t_end", "s"},
                               {"duration", "s"},
                               {"driving_force", "N"},
                               {"normal_load", "N"},
                               {"force_ratio", "1"},
                               {"nucleation_block", "1"},
                               {"nucleation_x", "m"},
                               {"extent", "m"},
                               {"extent_over_length", "1"},
                               {"min_ruptured_x", "m"},
                               {"max_ruptured_x", "m"},
                               {"ruptured_blocks", "1"},
                               {"global", "1"},
                               {"front_speed", "m/s"},
                               {"crossing_speed", "m/s"},
                               {"max_slip", "m"},
                               {"out_of_contact", "1"},
                               {"front_speed_error", "m/s"},
                               {"crossing_speed_error", "m/s"}}};
const ColumnTypes front_types{{"event", "block"},
                              {},
                              {{"event", "1"},
                               {"block", "1"},
                               {"x", "m"},
                               {"distance", "m"},
                               {"time", "s"},
                               {"delay", "s"},
                               {"resolution", "s"}}};
const ColumnTypes contact_types{
    {"block"}, {"in_contact"}, {{"time", "s"}, {"block", "1"}, {"x", "m"}, {"in_contact", "1"}}};

}  // namespace

namespace {
std::vector<OutputName> outputs(const Precursors::Params& p) {
    auto out = table_outputs("events_file", p.events_file, p.format);
    for (auto& o : table_outputs("fronts_file", p.fronts_file, p.format)) out.push_back(std::move(o));
    for (auto& o : table_outputs("contact_file", p.contact_file, p.format)) out.push_back(std::move(o));
    out.push_back({"summary_file", p.summary_file});
    return out;
}
}  // namespace

ParamSpec<Precursors::Params> Precursors::spec() {
    ParamSpec<Params> s(
        "Rupture events along the interface (precursors and global slips; Li et al. 2020 Figs. 6-8, "
        "theory.md B.19): start, F_S/F_N at nucleation, nucleation block, extent l/L, front, slip; "
        "as CSV tables and a summary with the global static coefficient.");
    s.choice(
        "criterion", &Params::criterion,
        {{"auto", Criterion::automatic}, {"pinned_fraction", Criterion::pinned_fraction}, {"slip", Criterion::slip}},
        "When a block is ruptured: 'pinned_fraction' (more than ruptured_fraction of its junctions are not "
        "pinned; needs the junction-count fields) or 'slip' (it slipped more than slip_threshold within "
        "quiet_time); 'auto': pinned_fraction where the friction law publishes junction counts, slip "
        "otherwise (run.yaml records which, under resolved_choices). Either way a block out of contact "
        "(lifted off) is not ruptured.");
    s.add("ruptured_fraction", &Params::ruptured_fraction,
          "Criterion pinned_fraction: fraction of a block's junctions that must be sliding or dislocated.")
        .unit("1")
        .at_least(0)
        .less_than(1);
    s.add("slip_threshold", &Params::slip_threshold, "Criterion slip: slip that makes a block ruptured.")
        .unit("m")
        .greater_than(0);
    s.add("quiet_time", &Params::quiet_time,
          "An event ends once this long has passed without a ruptured block; ruptures closer in time are one event.")
        .unit("s")
        .greater_than(0);
    s.add("front_every", &Params::front_every,
          "While an event runs, the observer samples this often (besides `every`), so that a front's arrival at a "
          "block, and its speed, are resolved finer than the table's cadence; 0: at `every` only.")
        .unit("s")
        .at_least(0);
    s.add("stage", &Params::stage,
          "Observe only during stages of this name (empty: every stage), so settling is not taken for rupture.")
        .names_a_stage();
    s.add("global_span", &Params::global_span,
          "An event is global (a global slip, not a precursor) when its ruptured blocks span at least this fraction "
          "of the interface length L, each block covering l_s (theory.md B.19a).")
        .unit("1")
        .greater_than(0)
        .at_most(1);
    s.add("nucleation_window_quiet_times", &Params::nucleation_window_quiet_times,
          "A non-global event ending at most this many quiet_times before a larger one (a longer precursor or a "
          "global slip) starts, within one block of its nucleation, is that rupture's nucleation and is reported "
          "with it (B.19a); in quiet times so that it scales with the loading rate as quiet_time does; 0: never.")
        .unit("1")
        .at_least(0);
    s.add("events_file", &Params::events_file,
          "File of the events, one row each, in the output directory (extension .h5 in HDF5).");
    s.add("fronts_file", &Params::fronts_file,
          "CSV file of the fronts: per event and block, when the block first ruptured.");
    s.add("contact_file", &Params::contact_file,
          "File of the blocks' lift-offs and re-contacts, one row each (in_contact 0: lifted off, 1: in contact "
          "again); a block is in contact while it has junctions, or without junction counts a normal force.");
    s.add("summary_file", &Params::summary_file, "YAML summary, rewritten atomically after each event.");
    add_table_format_param(s, &Params::format);
    add_outputs(s, outputs);
    return s;
}

Precursors::Precursors(const Params& p, const Context& ctx) : params_(spec().checked(p)) {
    if (params_.criterion == Criterion::automatic) {
        // Built after every effect: the junction counts are published by now, or never.
        const bool counts = ctx.quantities && JunctionCounts::published(*ctx.quantities);
        params_.criterion = counts ? Criterion::pinned_fraction : Criterion::slip;
        ctx.resolved("criterion", counts ? "pinned_fraction" : "slip",
                     counts ? "the friction law publishes junction counts"
                            : "no effect of this scene publishes junction counts");
    }
    if (params_.criterion == Criterion::pinned_fraction)
        counts_ = JunctionCounts::need(ctx,
                                       "set criterion: slip (or auto, which chooses slip without junction "
                                       "counts), or use a friction law with junctions");
}

void Precursors::begin(const RunView& view) {
    const Body& body = view.body;
    interface_ = body.nodes("interface");
    const auto n = static_cast<Index>(interface_.size());
    if (n == 0) throw RunError("precursors: the node set 'interface' is empty");

    if (params_.criterion == Criterion::slip) slip_criterion_.emplace(params_.slip_threshold, params_.quiet_time);

    RuptureEventDetector::Interface geometry;
    geometry.x.resize(n);
    for (Index i = 0; i < n; ++i) geometry.x(i) = body.x0(interface_[i]) - body.x0(interface_[0]);
    geometry.length = body.length > 0 ? body.length : geometry.x(n - 1);
    geometry.spacing = body.spacing;
    detector_.emplace(
        std::move(geometry), params_.quiet_time,
        RuptureEventDetector::Options{params_.global_span, params_.nucleation_window_quiet_times * params_.quiet_time});

    const Quantities& q = view.quantities;
    if (!counts_) counts_ = JunctionCounts::find(q, n);
    if (!counts_) {
        const Quantities::Field* f = q.find_field("normal_force");
        if (f && f->node_set == "interface" && f->values.size() == n)
            normal_force_ = &f->values;
        else
            view.log.warn(
                "precursors: neither junction counts nor 'normal_force' over the interface; every block "
                "is taken to be in contact");
    }
    if (const auto* s = q.find_scalar("driving_force"))
        driving_force_ = &s->value;
    else
        view.log.warn("precursors: no effect publishes 'driving_force'; F_S of the events is NaN");
    if (const auto* s = q.find_scalar("normal_load"))
        normal_load_ = &s->value;
    else
        view.log.warn("precursors: no effect publishes 'normal_load'; F_N of the events is NaN");

    slip_.resize(n);
    ruptured_.resize(n);
    contact_ = BlockMask::Constant(n, true);
    const TableFormat format = params_.format;
    const auto& out = view.output_directory;
    events_ = open_table(out / params_.events_file, event_columns, event_types, view.info, format, view.resuming);
    fronts_ = open_table(out / params_.fronts_file, front_columns, front_types, view.info, format, view.resuming);
    contact_table_ =
        open_table(out / params_.contact_file, contact_columns, contact_types, view.info, format, view.resuming);
    row_.reserve(event_columns.size());
    if (!view.resuming) write_summary(view, false);
}

void Precursors::classify(const RunView& view, bool rearm) {
    for (std::size_t i = 0; i < interface_.size(); ++i) {
        const Index node = interface_[i];
        slip_(static_cast<Index>(i)) = view.state.x(node) - view.body.x0(node);
    }
    if (params_.criterion == Criterion::pinned_fraction)
        ruptured_by_pinned_fraction(*counts_->pinned, *counts_->sliding, *counts_->dislocated,
                                    params_.ruptured_fraction, ruptured_);
    else if (rearm)
        slip_criterion_->apply(view.state.t, slip_, ruptured_);
    else
        slip_criterion_->peek(slip_, ruptured_);
    observe_contact(view);
}

void Precursors::observe_between(const RunView& view) {
    if (!detector_ || (!params_.stage.empty() && view.stage.name != params_.stage)) return;
    classify(view, false);
    detector_->observe_between(view.state.t, ruptured_, contact_, slip_);
}

void Precursors::observe(const RunView& view) {
    if (!detector_ || (!params_.stage.empty() && view.stage.name != params_.stage)) return;
    classify(view, true);
    const double f_s = driving_force_ ? *driving_force_ : nan;
    const double f_n = normal_load_ ? *normal_load_ : nan;
    if (auto ended = detector_->observe(view.state.t, ruptured_, contact_, slip_, f_s, f_n)) {
        write(*ended);
        write_summary(view, false);
    }
}

void Precursors::observe_contact(const RunView& view) {
    if (counts_)
        in_contact_by_junctions(*counts_->pinned, *counts_->sliding, *counts_->dislocated, contact_);
    else if (normal_force_)
        in_contact_by_normal_force(*normal_force_, contact_);
    const auto& changes = contact_changes_.observe(view.state.t, contact_);
    for (const ContactChange& c : changes)
        contact_table_->row({c.t, double(c.block), detector_->interface().x(c.block), c.in_contact ? 1.0 : 0.0});
}

void Precursors::end(const RunView& view) {
    if (!detector_) return;  // the run failed before its first stage: nothing to write
    while (auto e = detector_->close()) write(*e);
    write_summary(view, true);
}

void Precursors::write(const RuptureEvent& e) {
    row_.assign({double(e.index),
                 e.finished ? 1.0 : 0.0,
                 e.t_start,
                 e.t_end,
                 e.duration(),
                 e.driving_force,
                 e.normal_load,
                 e.force_ratio(),
                 double(e.nucleation),
                 e.nucleation_x,
                 e.extent,
                 e.extent_over_length,
                 e.min_x,
                 e.max_x,
                 double(e.ruptured_blocks),
                 e.global ? 1.0 : 0.0,
                 e.front_speed,
                 e.crossing_speed,
                 e.max_slip,
                 double(e.out_of_contact),
                 e.front_speed_error,
                 e.crossing_speed_error});
    events_->row(row_);
    const Eigen::ArrayXd& x = detector_->interface().x;
    for (std::size_t i = 0; i < e.first_rupture.size(); ++i) {
        const double t = e.first_rupture[i];
        if (std::isnan(t)) continue;
        const double xi = x(static_cast<Index>(i));
        fronts_->row(
            {double(e.index), double(i), xi, std::abs(xi - e.nucleation_x), t, t - e.t_start, t - e.sampled_before[i]});
    }
}

std::string Precursors::summary_text(const RuptureSummary& s, const ContactChanges& contact, const RunInfo& info,
                                     bool run_ended) {
    std::string out;
    auto line = [&](std::string_view key, const std::string& value) { out += fmt::format("{}: {}\n", key, value); };
    out +=
        "# Rupture events (theory.md B.19, B.20). Numbers in SI units; null: not (yet) observed. A time counts from "
        "the run's start, a time _since_loading from when loading started.\n";
    line("run_ended", run_ended ? "true" : "false");
    line("event_count", std::to_string(s.events));
    line("global_slip_seen", s.global_seen ? "true" : "false");
    // Before the first global slip: a count only once there is one.
    line("precursor_count", s.global_seen ? std::to_string(s.precursors_before_global) : "null");
    line("global_slip_time", yaml_number(s.global_time));
    line("global_slip_time_since_loading", yaml_number(s.global_time - info.loading_start));
    line("global_slip_driving_force", yaml_number(s.global_driving_force));
    line("global_slip_normal_load", yaml_number(s.global_normal_load));
    line("global_slip_force_ratio", yaml_number(s.global_seen ? s.global_driving_force / s.global_normal_load : nan));
    line("peak_driving_force", yaml_number(s.peak_driving_force));
    line("peak_driving_force_time", yaml_number(s.peak_time));
    line("peak_driving_force_time_since_loading", yaml_number(s.peak_time - info.loading_start));
    line("lift_offs", std::to_string(contact.lift_offs()));
    line("re_contacts", std::to_string(contact.re_contacts()));
    line("blocks_out_of_contact", std::to_string(contact.out_of_contact()));
    out += "run:\n";
    out += Provenance::of(info).yaml(2);
    return out;
}

void Precursors::write_summary(const RunView& view, bool run_ended) const {
    // A reader (or a run killed mid-write) never sees half a summary.
    write_file_atomically(view.output_directory / params_.summary_file,
                          summary_text(detector_->summary(), contact_changes_, view.info, run_ended));
}

}  // namespace frictionlab
