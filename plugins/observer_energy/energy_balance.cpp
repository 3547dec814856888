#include "energy_balance.hpp"

#include <limits>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/output/output_file_name.hpp"
#include "frictionlab/output/table_writer.hpp"
#include "frictionlab/simulation/system.hpp"

namespace frictionlab {

namespace {
std::vector<OutputName> outputs(const EnergyBalance::Params& p) {
    return table_outputs("file", p.file, TableFormat::csv);
}
}  // namespace

ParamSpec<EnergyBalance::Params> EnergyBalance::spec() {
    ParamSpec<Params> s(
        "Energy bookkeeping as CSV: kinetic energy, each effect's stored energy and work, the "
        "loaders' input, damping and friction dissipation, and the residual of the work-energy "
        "theorem (switches the run's work accounting on).");
    s.add("file", &Params::file, "CSV file name, in the run's output directory.");
    add_outputs(s, outputs);
    s.dimensions({2, 3});
    return s;
}

EnergyBalance::EnergyBalance(const Params& p, const Context&) : params_(spec().checked(p)) {}

void EnergyBalance::begin(const RunView& view) {
    const System& system = view.system;
    if (!system.work_accounting())
        throw RunError(
            "energy observer: the system's work accounting is off (the run switches it on for an "
            "observer whose needs_work_accounting() is true, before the first step)");
    system.for_each_effect([&](const Effect& e) {
        effects_.push_back(&e);
        groups_.push_back(dynamic_cast<const Loader*>(&e)        ? Group::loader
                          : dynamic_cast<const FrictionLaw*>(&e) ? Group::friction
                                                                 : Group::bulk);
    });
    std::vector<std::string> names{"time", "step", "stage", "kinetic_energy"};
    ColumnTypes types{
        {"step", "stage"}, {}, {{"time", "s"}, {"step", "1"}, {"stage", "1"}, {"relative_residual", "1"}}};
    for (std::size_t k = 0; k < effects_.size(); ++k) {
        const std::string& label = system.labels()[k];
        names.push_back(label + "_energy");
        names.push_back(label + "_work");
        names.push_back(label + (groups_[k] == Group::loader ? "_input" : "_dissipated"));
    }
    for (const char* total : {"stored_energy", "input", "dissipated_damping", "dissipated_friction", "residual",
                              "relative_residual", "balance_error"})
        names.push_back(total);
    for (const auto& name : names) types.units.emplace(name, "J");  // every energy, work and balance
    table_ = open_table(view.output_directory / params_.file, names, types, view.info, TableFormat::csv, view.resuming);
    row_.reserve(names.size());
    stored_.resize(effects_.size());
}

double EnergyBalance::kinetic_energy(const RunView& view) {
    const auto& v = view.state.velocity;
    Eigen::ArrayXd speed_squared = v.col(0).square();
    for (Index axis = 1; axis < v.cols(); ++axis) speed_squared += v.col(axis).square();
    return 0.5 * (view.body.mass * speed_squared).sum();
}

void EnergyBalance::observe(const RunView& view) {
    const std::vector<double>& work = view.system.work();
    const double kinetic = kinetic_energy(view);
    for (std::size_t k = 0; k < effects_.size(); ++k) stored_[k] = effects_[k]->potential_energy(view.state);
    if (!reference_) reference_ = Reference{kinetic, stored_, work};

    row_.clear();
    row_.push_back(view.state.t);
    row_.push_back(static_cast<double>(view.step));
    row_.push_back(view.stage.index);
    row_.push_back(kinetic);
    double stored = 0, stored_change = 0, total_work = 0, input = 0, damping = 0, friction = 0;
    for (std::size_t k = 0; k < effects_.size(); ++k) {
        const double w = work[k] - reference_->work[k], de = stored_[k] - reference_->stored[k];
        // Loaders: what their outside source put in; the others: what they took out for good.
        const double released = groups_[k] == Group::loader ? w + de : -w - de;
        row_.push_back(stored_[k]);
        row_.push_back(w);
        row_.push_back(released);
        stored += stored_[k];
        stored_change += de;
        total_work += w;
        (groups_[k] == Group::loader ? input : groups_[k] == Group::friction ? friction : damping) += released;
    }
    const double kinetic_change = kinetic - reference_->kinetic;
    const double residual = kinetic_change - total_work;
    row_.push_back(stored);
    row_.push_back(input);
    row_.push_back(damping);
    row_.push_back(friction);
    row_.push_back(residual);
    row_.push_back(input > 0 ? residual / input : std::numeric_limits<double>::quiet_NaN());
    row_.push_back(kinetic_change + stored_change + damping + friction - input);
    table_->row(row_);
}

}  // namespace frictionlab
