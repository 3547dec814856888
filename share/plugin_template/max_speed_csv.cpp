// An out-of-tree FrictionLab plugin with one observer: at the cadence the scene sets, it writes the
// largest node speed of the slider to a table in the run's output directory. The framework's table
// writer does the writing, so the table gets what the shipped observers' tables get: the run's
// provenance beside it, CSV or HDF5 as the scene chooses, whole rows only, and a resumed run's
// table cut back to the checkpoint and appended to.
#include <memory>
#include <string>
#include <string_view>

#include <frictionlab/base/param_spec.hpp>
#include <frictionlab/model/kinds.hpp>
#include <frictionlab/output/output_file_name.hpp>
#include <frictionlab/output/table_writer.hpp>
#include <frictionlab/plugins/plugin.hpp>
#include <frictionlab/plugins/registry.hpp>
#include <frictionlab/simulation/run.hpp>

namespace {

using frictionlab::RunView;

/// max_i |v_i| over every node: a quick way to see when the slider slips and when it has settled.
/// Columns: time (s), step, max_speed (m/s). It reads the velocities as the N x d array the state
/// view gives, so it works on a body of any dimension, and says so.
class MaxSpeedCsv final : public frictionlab::Observer {
public:
    // Defaults live here, and only here.
    struct Params {
        std::string file_name = "max_speed.csv";
        frictionlab::TableFormat format = frictionlab::TableFormat::csv;
    };
    // The name a scene gives as `type:` under `observers:`.
    static constexpr std::string_view type = "max_speed_csv";

    // Docs, units, bounds and rules of every key, read by scene validation and `frictionlab doc`.
    static frictionlab::ParamSpec<Params> spec() {
        frictionlab::ParamSpec<Params> s("Largest node speed of the slider over time, as a table.");
        s.add("file_name", &Params::file_name, "Name of the table in the run's output directory.");
        s.rule("file_name", [](const Params& p) { return frictionlab::output_file_name_problem(p.file_name); });
        frictionlab::add_table_format_param(s, &Params::format);
        // The bodies it works on: 2D and 3D (a type that declares nothing works in 2D only, and
        // `check` refuses a 3D scene naming it).
        s.dimensions({2, 3});
        return s;
    }

    // spec().checked(): Params built in code pass the checks a scene's values pass.
    MaxSpeedCsv(const Params& params, const frictionlab::Context&) : params_(spec().checked(params)) {}

    // Checkpoints: it keeps nothing but its table, which a resumed run cuts back and appends to.
    bool checkpointable() const override { return true; }

    void begin(const RunView& view) override {
        // Every column's unit, and which hold integers: the table's sidecar records them.
        const frictionlab::ColumnTypes types{{"step"}, {}, {{"time", "s"}, {"step", "1"}, {"max_speed", "m/s"}}};
        table_ = frictionlab::open_table(view.output_directory / params_.file_name, {"time", "step", "max_speed"},
                                         types, view.info, params_.format, view.resuming);
    }

    void observe(const RunView& view) override {
        const auto& s = view.state;
        // s.velocity is [nodes, dimension]: row i is node i's velocity, whatever the dimension.
        const double max_speed = s.velocity.rows() == 0 ? 0.0 : s.velocity.matrix().rowwise().norm().maxCoeff();
        table_->row({s.t, static_cast<double>(view.step), max_speed});
    }

private:
    Params params_;
    std::unique_ptr<frictionlab::TableWriter> table_;
};

// Called once when the library is loaded: an ordinary call per type, nothing registers itself.
void register_types(frictionlab::Registry& registry) { registry.add<MaxSpeedCsv>(); }

}  // namespace

// The library's one exported symbol: its name (the file's name), version and register function.
FRICTIONLAB_PLUGIN("observer_max_speed_csv", "0.1.0", register_types)
