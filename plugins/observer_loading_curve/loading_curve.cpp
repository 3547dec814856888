#include "loading_curve.hpp"

#include <limits>

#include "frictionlab/output/output_file_name.hpp"
#include "frictionlab/output/table_writer.hpp"

namespace frictionlab {

namespace {
std::vector<OutputName> outputs(const LoadingCurve::Params& p) {
    return table_outputs("file", p.file, TableFormat::csv);
}
}  // namespace

ParamSpec<LoadingCurve::Params> LoadingCurve::spec() {
    ParamSpec<Params> s(
        "Loading curve (Li et al. 2020, Fig. 6): driving force F_S, F_S/F_N, total friction and "
        "normal force, driving-point displacement against time, as CSV.");
    s.add("file", &Params::file, "CSV file name, in the run's output directory.");
    add_outputs(s, outputs);
    s.dimensions({2, 3});
    return s;
}

LoadingCurve::LoadingCurve(const Params& p, const Context&) : params_(spec().checked(p)) {}

void LoadingCurve::begin(const RunView& view) {
    const Quantities& q = view.quantities;
    ColumnTypes types{{"step", "stage"}, {}, {{"time", "s"}, {"step", "1"}, {"stage", "1"}}};
    const auto scalar = [&](const char* name, const char* column) {
        if (const auto* s = q.find_scalar(name)) {
            columns_.push_back({column, &s->value, nullptr});
            types.units[column] = s->unit;
        }
    };
    const auto total = [&](const char* name, const char* column) {
        if (const auto* f = q.find_field(name)) {
            columns_.push_back({column, nullptr, &f->values});
            types.units[column] = f->unit;
        }
    };
    scalar("driving_force", "driving_force");
    scalar("driving_displacement", "driving_displacement");
    scalar("driver_position", "driver_position");
    scalar("normal_load", "normal_load");
    total("friction_force", "total_friction_force");
    total("normal_force", "total_normal_force");
    if (const auto* s = q.find_scalar("normal_load")) normal_load_ = &s->value;
    if (const auto* s = q.find_scalar("driving_force")) driving_force_ = &s->value;

    std::vector<std::string> names{"time", "step", "stage"};
    for (const auto& c : columns_) names.push_back(c.name);
    if (normal_load_ && driving_force_) names.push_back("driving_force_over_normal_load");
    types.units["driving_force_over_normal_load"] = "1";
    table_ = open_table(view.output_directory / params_.file, names, types, view.info, TableFormat::csv, view.resuming);
    row_.reserve(names.size());
}

void LoadingCurve::observe(const RunView& view) {
    row_.clear();
    row_.push_back(view.state.t);
    row_.push_back(static_cast<double>(view.step));
    row_.push_back(view.stage.index);
    for (const auto& c : columns_) row_.push_back(c.scalar ? *c.scalar : c.field->sum());
    if (normal_load_ && driving_force_)
        row_.push_back(*normal_load_ > 0 ? *driving_force_ / *normal_load_ : std::numeric_limits<double>::quiet_NaN());
    table_->row(row_);
}

}  // namespace frictionlab
