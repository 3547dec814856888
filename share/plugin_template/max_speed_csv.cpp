// An out-of-tree FrictionLab plugin with one observer: at the cadence the scene sets, it writes the
// largest node speed of the slider to a CSV table in the run's output directory.
#include <fstream>
#include <string>
#include <string_view>

#include <frictionlab/base/errors.hpp>
#include <frictionlab/model/kinds.hpp>
#include <frictionlab/base/param_spec.hpp>
#include <frictionlab/plugins/plugin.hpp>
#include <frictionlab/plugins/registry.hpp>
#include <frictionlab/simulation/run.hpp>

namespace {

using frictionlab::RunView;

/// max_i sqrt(vx_i^2 + vz_i^2) over every node: a quick way to see when the slider slips and when it
/// has settled. Columns: time (s), step, max_speed (m/s).
class MaxSpeedCsv final : public frictionlab::Observer {
public:
    // Defaults live here, and only here.
    struct Params {
        std::string file_name = "max_speed.csv";
    };
    // The name a scene gives as `type:` under `observers:`.
    static constexpr std::string_view type = "max_speed_csv";

    // Docs, units and bounds of every key, read by scene validation and `frictionlab doc`.
    static frictionlab::ParamSpec<Params> spec() {
        frictionlab::ParamSpec<Params> s("Largest node speed of the slider over time, as a CSV table.");
        s.add("file_name", &Params::file_name, "Name of the table in the run's output directory.");
        return s;
    }

    MaxSpeedCsv(const Params& params, const frictionlab::Context&) : params_(params) {}

    void begin(const RunView& view) override {
        const auto path = view.output_directory / params_.file_name;
        out_.open(path);
        if (!out_) throw frictionlab::RunError("max_speed_csv: cannot write " + path.string());
        out_.precision(10);
        out_ << "time,step,max_speed\n";
    }

    void observe(const RunView& view) override {
        const auto& s = view.state;
        const double max_speed = s.vx.size() == 0 ? 0.0 : (s.vx.square() + s.vz.square()).sqrt().maxCoeff();
        out_ << s.t << ',' << view.step << ',' << max_speed << '\n';
    }

    // Also called when the run fails: what was written so far stays a valid table.
    void end(const RunView&) override { out_.flush(); }

private:
    Params params_;
    std::ofstream out_;
};

// Called once when the library is loaded: an ordinary call per type, nothing registers itself.
void register_types(frictionlab::Registry& registry) { registry.add<MaxSpeedCsv>(); }

}  // namespace

// The library's one exported symbol: its name (the file's name), version and register function.
FRICTIONLAB_PLUGIN("observer_max_speed_csv", "0.1.0", register_types)
