#include "precursors.hpp"

#include <algorithm>

#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/model/rupture_scales.hpp"
#include "frictionlab/output/atomic_file.hpp"
#include "frictionlab/output/output_file_name.hpp"
#include "frictionlab/output/provenance.hpp"

namespace frictionlab {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The auto settings as fractions of the scene's scales (theory.md §5a says why these).
constexpr double quiet_fraction_of_drive = 0.5;     // quiet_speed = this x the drive's speed
constexpr double quiet_time_in_windows = 2;         // quiet_time = this x rate_window
constexpr double min_slip_in_characteristic = 0.1;  // min_slip = this x the law's characteristic slip

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
                                             "crossing_speed_error",
                                             "slip_extent"};
const std::vector<std::string> front_columns{"event", "block", "x", "distance", "time", "delay", "resolution"};
// On a 2D interface (a 3D body), the events' and fronts' columns across the width, after the others.
const std::vector<std::string> event_columns_across{"nucleation_y", "min_ruptured_y", "max_ruptured_y", "extent_across",
                                                    "area_fraction"};
const std::map<std::string, std::string> units_across{{"nucleation_y", "m"},   {"min_ruptured_y", "m"},
                                                      {"max_ruptured_y", "m"}, {"extent_across", "m"},
                                                      {"area_fraction", "1"},  {"y", "m"}};

/// The columns, and their types, of a table on a line or, `across`, with the columns across appended.
std::pair<std::vector<std::string>, ColumnTypes> with_across(std::vector<std::string> columns, ColumnTypes types,
                                                             const std::vector<std::string>& across) {
    for (const auto& c : across) columns.push_back(c), types.units[c] = units_across.at(c);
    return {std::move(columns), std::move(types)};
}
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
                               {"crossing_speed_error", "m/s"},
                               {"slip_extent", "m"}}};
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

std::vector<OutputName> outputs(const Precursors::Params& p) {
    auto out = table_outputs("events_file", p.events_file, p.format);
    for (auto& o : table_outputs("fronts_file", p.fronts_file, p.format)) out.push_back(std::move(o));
    for (auto& o : table_outputs("contact_file", p.contact_file, p.format)) out.push_back(std::move(o));
    out.push_back({"summary_file", p.summary_file});
    return out;
}

std::string number(double v) { return fmt::format("{:.4g}", v); }

const std::vector<std::string> none, y_column{"y"};

}  // namespace

ParamSpec<Precursors::Params> Precursors::spec() {
    ParamSpec<Params> s(
        "Rupture events on the interface, a line of blocks or a 3D body's 2D grid (precursors and global slips; "
        "Li et al. 2020 Figs. 6-8, theory.md §5a): start, F_S/F_N at nucleation, nucleation block, extent l/L "
        "(and across, and its area, on a 2D interface), front, slip; each run's "
        "global slips checked against the drops of its loading curve and its precursors against its slip field; "
        "as CSV tables and a summary with the settings used and the verdict of the check.");
    s.choice("criterion", &Params::criterion,
             {{"auto", Criterion::automatic},
              {"pinned_fraction", Criterion::pinned_fraction},
              {"slipping", Criterion::slipping},
              {"slip_rate", Criterion::slip_rate}},
             "Whether a block's contact is broken: 'pinned_fraction' (more than ruptured_fraction of its junctions "
             "are not pinned; needs junction counts), 'slipping' (the law's stuck spring is broken; needs its field "
             "'slipping'), 'slip_rate' (no contact measure: the slip rate alone decides); 'auto': the first the "
             "friction law allows (run.yaml records which, under resolved_choices). A block must besides slip faster "
             "than quiet_speed, and one out of contact (lifted off) never ruptures.");
    s.add("ruptured_fraction", &Params::ruptured_fraction,
          "Criterion pinned_fraction: fraction of a block's junctions that must be sliding or dislocated.")
        .unit("1")
        .at_least(0)
        .less_than(1);
    s.add("quiet_speed", &Params::quiet_speed,
          "A block slipping slower than this (its mean rate over rate_window) creeps with the load and does not "
          "rupture; auto: half the drive's speed.")
        .unit("m/s")
        .greater_than(0)
        .or_auto();
    s.add("rate_window", &Params::rate_window,
          "Time over which a block's slip rate is averaged; auto: the time L/c_S a shear wave takes to cross the "
          "slider, over which its vibrations average out.")
        .unit("s")
        .greater_than(0)
        .or_auto()
        .within_stage("stage");
    s.add("quiet_time", &Params::quiet_time,
          "A block rupturing within one block of an event's rupturing block at most this long after it joins that "
          "event; an event ends once none of its blocks has ruptured for this long; auto: twice rate_window.")
        .unit("s")
        .greater_than(0)
        .or_auto()
        .within_stage("stage");
    s.add("min_slip", &Params::min_slip,
          "An event none of whose blocks slipped this much is not reported (vibration or a junction's flicker); "
          "auto: a tenth of the friction law's characteristic slip (its published characteristic_slip).")
        .unit("m")
        .greater_than(0)
        .or_auto();
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
    s.add("nucleation_load", &Params::nucleation_load,
          "A rupture's nucleation: an event that is not global is reported with a larger one nucleating within "
          "one block of it, which starts after it ended, before F_S has risen by this fraction of F_N (theory.md "
          "§5a); in load, not time, so that it means the same at every drive; 0: never.")
        .unit("1")
        .at_least(0);
    s.add("drop_threshold", &Params::drop_threshold,
          "The check of the events: a fall of F_S/F_N by at least this much is a drop of the loading curve, "
          "which exactly one global slip must match; a fall by a third of it goes beyond a slip's ringing, and a "
          "global slip may lie in it.")
        .unit("1")
        .greater_than(0);
    s.add("match_tolerance", &Params::match_tolerance,
          "The check of the events: a global slip must start within this fraction of its drop's peak F_S/F_N.")
        .unit("1")
        .greater_than(0);
    s.add("check", &Params::check,
          "Check the events against the loading curve's drops and the slip field (theory.md §5a); false skips "
          "the check (verdict: not_checked), for a run that measures what it costs.");
    s.choice("end_stage", &Params::end_stage,
             {{"never", EndStage::never}, {"after_global_slip", EndStage::after_global_slip}},
             "'after_global_slip': end the stage the first global slip happens in once that slip is over (reported "
             "ended, and with the check on the loading curve risen again after its fall), for a run that measures "
             "the static coefficient and the precursors before it; later stages still run, and run.yaml records the "
             "early end under stages_ended_early. 'never': every stage runs its duration.");
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
    s.dimensions({2, 3});
    return s;
}

Precursors::Precursors(const Params& p, const Context& ctx) : params_(spec().checked(p)) {
    if (!ctx.quantities || !ctx.body) throw InputError("precursors needs the run's body and quantities");
    const Quantities& q = *ctx.quantities;
    // Built after every effect: what they publish is declared by now, or never.
    if (params_.criterion == Criterion::automatic) {
        const bool counts = JunctionCounts::published(q);
        const auto* slipping = q.find_field(rupture_scales::slipping_name);
        params_.criterion = counts                            ? Criterion::pinned_fraction
                            : slipping && slipping->published ? Criterion::slipping
                                                              : Criterion::slip_rate;
        ctx.resolved("criterion",
                     counts     ? "pinned_fraction"
                     : slipping ? "slipping"
                                : "slip_rate",
                     counts     ? "the friction law publishes junction counts"
                     : slipping ? "the friction law publishes whether a block slips"
                                : "the friction law publishes no contact measure");
    }
    if (params_.criterion == Criterion::pinned_fraction)
        counts_ = JunctionCounts::need(ctx,
                                       "set criterion: slip_rate (or auto, which chooses what the law allows), or "
                                       "use a friction law with junctions");
    if (params_.criterion == Criterion::slipping) {
        const auto blocks = static_cast<Index>(ctx.body->nodes("interface").size());
        slipping_ = &ctx.quantities->needed_field(std::string(rupture_scales::slipping_name), "interface", blocks,
                                                  ctx.name, "set criterion: slip_rate or auto");
    }

    if (std::isnan(params_.quiet_speed)) {
        const double v = rupture_scales::find(q, rupture_scales::drive_velocity_name);
        if (std::isnan(v) && !ctx.effects_refused)
            throw InputError(
                "quiet_speed is auto, half the drive's speed, but no loader of this scene publishes a "
                "drive_velocity (a driving_spring or plate_springs does): set quiet_speed in m/s");
        if (v == 0)
            throw InputError(
                "quiet_speed is auto, half the drive's speed, but the drive stands still (its velocity is 0): "
                "set quiet_speed in m/s, or give the drive a velocity");
        params_.quiet_speed = quiet_fraction_of_drive * v;  // NaN when the drive was refused: no run follows
        if (v > 0)
            ctx.resolved("quiet_speed", number(params_.quiet_speed), fmt::format("half the drive's {} m/s", number(v)));
    }
    if (std::isnan(params_.rate_window)) {
        const Body& body = *ctx.body;
        if (!(body.length > 0 && body.wave_speed > 0))
            throw InputError(
                "rate_window is auto, the time a wave takes to cross the body, but the bulk model gives "
                "no length or wave speed: set rate_window in s");
        params_.rate_window = body.length / body.wave_speed;
        ctx.resolved("rate_window", number(params_.rate_window),
                     fmt::format("L/c_S = {} m / {} m/s", number(body.length), number(body.wave_speed)));
    }
    if (std::isnan(params_.quiet_time)) {
        params_.quiet_time = quiet_time_in_windows * params_.rate_window;
        ctx.resolved("quiet_time", number(params_.quiet_time), "twice rate_window");
    }
    if (const auto* s = q.find_scalar(rupture_scales::characteristic_slip_name)) law_slip_scale_ = &s->value;
    kinetic_coefficient_ = rupture_scales::find(q, rupture_scales::kinetic_coefficient_name);
    if (std::isnan(params_.min_slip)) {
        if (!law_slip_scale_) {
            params_.min_slip = 0;
            ctx.resolved("min_slip", "0",
                         "no friction law of this scene publishes a characteristic slip: every event is reported");
        } else if ((min_slip_follows_law_ = std::isnan(*law_slip_scale_))) {
            ctx.resolved("min_slip", "a tenth of the law's characteristic slip when loading starts",
                         "the law's scale follows the normal force");
        } else {
            characteristic_slip_ = *law_slip_scale_;
            params_.min_slip = min_slip_in_characteristic * characteristic_slip_;
            ctx.resolved("min_slip", number(params_.min_slip),
                         fmt::format("a tenth of the law's characteristic slip {} m", number(characteristic_slip_)));
        }
    } else if (law_slip_scale_) {
        characteristic_slip_ = *law_slip_scale_;
    }
    drops_ = LoadingDrops(params_.drop_threshold);
    slip_rate_ = SlipRate(params_.rate_window);
}

void Precursors::begin(const RunView& view) {
    const Body& body = view.body;
    interface_ = body.nodes("interface");
    const auto n = static_cast<Index>(interface_.size());
    if (n == 0) throw RunError("precursors: the node set 'interface' is empty");

    RuptureEventDetector::Interface geometry = interface_geometry(body, interface_);
    detector_.emplace(std::move(geometry),
                      RuptureEventDetector::Options{params_.quiet_time, params_.global_span,
                                                    min_slip_follows_law_ ? nan : params_.min_slip,
                                                    characteristic_slip_, params_.nucleation_load, params_.quiet_time});

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
    rate_.resize(n);
    rupturing_.resize(n);
    fast_.resize(n);
    broke_at_ = Eigen::ArrayXd::Constant(n, nan);
    intact_at_ = Eigen::ArrayXd::Constant(n, nan);
    contact_ = BlockMask::Constant(n, true);
    const TableFormat format = params_.format;
    const auto& out = view.output_directory;
    const bool plane = detector_->interface().plane();
    const auto [events, events_types] = with_across(event_columns, event_types, plane ? event_columns_across : none);
    const auto [fronts, fronts_types] = with_across(front_columns, front_types, plane ? y_column : none);
    events_ = open_table(out / params_.events_file, events, events_types, view.info, format, view.resuming);
    fronts_ = open_table(out / params_.fronts_file, fronts, fronts_types, view.info, format, view.resuming);
    contact_table_ =
        open_table(out / params_.contact_file, contact_columns, contact_types, view.info, format, view.resuming);
    row_.reserve(event_columns.size());
    if (!view.resuming) write_summary(view, false);
}

void Precursors::classify(const RunView& view, bool record) {
    for (std::size_t i = 0; i < interface_.size(); ++i) {
        const Index node = interface_[i];
        slip_(static_cast<Index>(i)) = view.state.x(node) - view.body.x0()(node);
    }
    switch (params_.criterion) {
        case Criterion::pinned_fraction:
            ruptured_by_pinned_fraction(*counts_->pinned, *counts_->sliding, *counts_->dislocated,
                                        params_.ruptured_fraction, rupturing_);
            break;
        case Criterion::slipping:
            ruptured_by_slipping(*slipping_, rupturing_);
            break;
        default:
            rupturing_.setConstant(true);
    }
    observe_contact(view);
    // When each contact broke: a rupture's front passed it then (no contact measure: unknown).
    const double t = view.state.t;
    const bool measured = params_.criterion != Criterion::slip_rate;
    for (Index i = 0; i < rupturing_.size(); ++i) {
        if (!(measured && rupturing_(i) && contact_(i)))
            broke_at_(i) = nan;
        else if (std::isnan(broke_at_(i)))
            broke_at_(i) = t, intact_at_(i) = std::isnan(last_observed_) ? t : last_observed_;
    }
    last_observed_ = t;
    slip_rate_.rate(t, slip_, rate_);
    fast_ = rate_ > params_.quiet_speed;
    rupturing_ = rupturing_ && fast_;
    if (record) slip_rate_.record(t, slip_);
}

void Precursors::observe_between(const RunView& view) {
    if (!detector_ || (!params_.stage.empty() && view.stage.name != params_.stage)) return;
    classify(view, false);
    detector_->observe_between(view.state.t, {rupturing_, contact_, fast_, slip_, broke_at_, intact_at_});
}

void Precursors::observe(const RunView& view) {
    if (!detector_ || (!params_.stage.empty() && view.stage.name != params_.stage)) return;
    if (min_slip_follows_law_ && law_slip_scale_ && std::isfinite(*law_slip_scale_)) {
        // The law's scale is known once loads act: the first observation of the stage fixes it.
        characteristic_slip_ = *law_slip_scale_;
        params_.min_slip = min_slip_in_characteristic * characteristic_slip_;
        detector_->set_slip_scales(params_.min_slip, characteristic_slip_);
        min_slip_follows_law_ = false;
    }
    classify(view, true);
    const double f_s = driving_force_ ? *driving_force_ : nan;
    const double f_n = normal_load_ ? *normal_load_ : nan;
    detector_->observe(view.state.t, {rupturing_, contact_, fast_, slip_, broke_at_, intact_at_}, f_s, f_n);
    if (params_.check) drops_.observe(view.state.t, f_s / f_n);
    report_ended(view);
    judge_stage_end(view);
}

void Precursors::judge_stage_end(const RunView& view) {
    if (params_.end_stage != EndStage::after_global_slip || stage_to_end_ >= 0) return;
    const auto first_global =
        std::find_if(checked_.begin(), checked_.end(), [](const CheckedEvent& e) { return e.global; });
    if (first_global == checked_.end() || !first_global->finished || (params_.check && drops_.falling())) return;
    stage_end_ = fmt::format("the first global slip (event {}, F_S/F_N {:.4f}) is over", first_global->index,
                             first_global->force_ratio);
    stage_to_end_ = view.stage.index;
}

void Precursors::report_ended(const RunView& view) {
    bool any = false;
    while (auto e = detector_->next_reported()) {
        write(*e);
        checked_.push_back({e->index, e->global, e->finished, e->t_start, e->force_ratio(), e->extent, e->slip_extent});
        any = true;
    }
    if (any) write_summary(view, false);
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
    detector_->close();
    report_ended(view);
    write_summary(view, true);
    const EventCheck c = check();
    if (!params_.check || c.agree()) return;
    std::string problems;
    for (const auto& p : c.problems) problems += "\n  " + p;
    view.log.warn(
        "precursors: the rupture events disagree with the loading curve or the slip field ({} of {}; "
        "{}):{}",
        c.problems.size() == 1 ? "one problem" : fmt::format("{} problems", c.problems.size()), params_.summary_file,
        "theory.md §5a says what each check means", problems);
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
                 e.crossing_speed_error,
                 e.slip_extent});
    if (detector_->interface().plane())
        row_.insert(row_.end(), {e.nucleation_y, e.min_y, e.max_y, e.extent_across, e.area_fraction});
    events_->row(row_);
    const Eigen::ArrayXd& x = detector_->interface().x;
    for (std::size_t i = 0; i < e.first_rupture.size(); ++i) {
        if (!e.in_extent(i) && static_cast<int>(i) != e.nucleation) continue;
        const double t = e.first_rupture[i];
        const double xi = x(static_cast<Index>(i));
        const auto block = static_cast<Index>(i);
        const RuptureEventDetector::Interface& at = detector_->interface();
        if (at.plane())
            fronts_->row({double(e.index), double(i), xi, std::hypot(xi - e.nucleation_x, at.y(block) - e.nucleation_y),
                          t, t - e.t_start, t - e.sampled_before[i], at.y(block)});
        else
            fronts_->row({double(e.index), double(i), xi, std::abs(xi - e.nucleation_x), t, t - e.t_start,
                          t - e.sampled_before[i]});
    }
}

EventCheck Precursors::check() const {
    if (!params_.check) return {};
    EventCheckOptions o;
    o.match_tolerance = params_.match_tolerance;
    o.kinetic_coefficient = kinetic_coefficient_;
    o.spacing = detector_->interface().spacing;
    return check_events(drops_.falls(), checked_, o);
}

std::string Precursors::summary_text(const RunView& view, const EventCheck& c, bool run_ended) const {
    const RuptureSummary& s = detector_->summary();
    const double t0 = view.info.loading_start;
    std::string out;
    auto line = [&](std::string_view key, const std::string& value) { out += fmt::format("{}: {}\n", key, value); };
    out +=
        "# Rupture events (theory.md §5a, B.20). Numbers in SI units; times on the run's clock, or since\n"
        "# loading started where the key says so; null: not (yet) observed.\n";
    line("run_ended", run_ended ? "true" : "false");
    line("event_count", std::to_string(s.events));
    line("global_slip_seen", s.global_seen ? "true" : "false");
    line("precursor_count", s.global_seen ? std::to_string(s.precursors_before_global) : "null");
    line("global_slip_time", yaml_number(s.global_time));
    line("global_slip_time_since_loading", yaml_number(s.global_time - t0));
    line("global_slip_driving_force", yaml_number(s.global_driving_force));
    line("global_slip_normal_load", yaml_number(s.global_normal_load));
    line("global_slip_force_ratio", yaml_number(s.global_seen ? s.global_force_ratio() : nan));
    line("peak_driving_force", yaml_number(s.peak_driving_force));
    line("peak_driving_force_time", yaml_number(s.peak_time));
    line("peak_driving_force_time_since_loading", yaml_number(s.peak_time - t0));
    line("events_too_small", std::to_string(s.too_small));
    line("lift_offs", std::to_string(contact_changes_.lift_offs()));
    line("re_contacts", std::to_string(contact_changes_.re_contacts()));
    line("blocks_out_of_contact", std::to_string(contact_changes_.out_of_contact()));
    if (!stage_end_.empty()) line("stage_ended_early", fmt::format("\"{}\"", stage_end_));  // end_stage
    // What decided the events, every auto resolved: enough to run the detector again by hand.
    const auto& o = detector_->options();
    const char* criteria[] = {"auto", "pinned_fraction", "slipping", "slip_rate"};
    out += fmt::format(
        "settings: {{criterion: {}, ruptured_fraction: {}, quiet_speed: {}, rate_window: {}, quiet_time: {}, "
        "min_slip: {}, characteristic_slip: {}, kinetic_coefficient: {}, global_span: {}, nucleation_load: {}, "
        "drop_threshold: {}, match_tolerance: {}}}\n",
        criteria[static_cast<int>(params_.criterion)], yaml_number(params_.ruptured_fraction),
        yaml_number(params_.quiet_speed), yaml_number(params_.rate_window), yaml_number(o.quiet_time),
        yaml_number(o.min_slip), yaml_number(o.characteristic_slip), yaml_number(kinetic_coefficient_),
        yaml_number(o.global_span), yaml_number(o.nucleation_load), yaml_number(params_.drop_threshold),
        yaml_number(params_.match_tolerance));
    out +=
        "# The events checked (theory.md §5a): global slips against the falls of F_S/F_N (drop: by at least\n"
        "# drop_threshold, which a global slip must match), precursors against the slip field.\n"
        "# verdict: agree, or disagree with the problems listed.\n";
    out += "event_check:\n";
    out += fmt::format("  verdict: {}\n", !params_.check ? "not_checked" : c.agree() ? "agree" : "disagree");
    const auto& falls = drops_.falls();
    out += "  falls:";
    if (falls.empty()) out += " []";
    out += "\n";
    for (std::size_t d = 0; d < falls.size(); ++d)
        out += fmt::format(
            "    - {{peak_time_since_loading: {}, peak_force_ratio: {}, trough_force_ratio: {}, drop: {}, ended: {}, "
            "global_slip_event: {}}}\n",
            yaml_number(falls[d].peak_time - t0), yaml_number(falls[d].peak_ratio), yaml_number(falls[d].trough_ratio),
            falls[d].major ? "true" : "false", falls[d].ended ? "true" : "false",
            c.drop_event[d] >= 0 ? std::to_string(c.drop_event[d]) : "null");
    out += "  problems:";
    if (c.problems.empty()) out += " []";
    out += "\n";
    for (const auto& p : c.problems) out += fmt::format("    - \"{}\"\n", p);
    out += "run:\n";
    out += Provenance::of(view.info).yaml(2);
    return out;
}

void Precursors::write_summary(const RunView& view, bool run_ended) const {
    // A reader (or a run killed mid-write) never sees half a summary.
    write_file_atomically(view.output_directory / params_.summary_file, summary_text(view, check(), run_ended));
}

}  // namespace frictionlab
