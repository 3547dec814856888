// check_template <observer_max_speed_csv.so> <output directory>
// Loads the plugin built from share/plugin_template through the installed library, runs its
// observer on a two-node state whose largest speed is known (|(3, 4)| = 5 m/s) and checks the table,
// written by the framework's table writer with the run's provenance beside it; then on a 3D body
// (|(2, 3, 6)| = 7 m/s), as the type says it works in 2D and 3D.
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <spdlog/logger.h>

#include <frictionlab/base/errors.hpp>
#include <frictionlab/model/quantities.hpp>
#include <frictionlab/plugins/registry.hpp>
#include <frictionlab/simulation/run.hpp>
#include <frictionlab/simulation/system.hpp>

namespace fl = frictionlab;

namespace {
int fail(const std::string& why) {
    std::cerr << "check_template: " << why << '\n';
    return 1;
}
}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) return fail("usage: check_template <plugin.so> <output directory>");
    const std::filesystem::path plugin = argv[1], output = argv[2];
    try {
        fl::Registry registry;
        const fl::PluginRecord record = registry.load(plugin);
        if (record.name != "observer_max_speed_csv" || record.version != "0.1.0")
            return fail("unexpected plugin " + record.name + " " + record.version);
        const fl::TypeInfo* info = registry.find(fl::Kind::observer, "max_speed_csv");
        if (!info) return fail("the plugin did not register observer type 'max_speed_csv'");
        if (info->params.size() != 2 || info->params[0].key != "file_name" || info->params[1].key != "format")
            return fail("observer 'max_speed_csv' should declare two keys, file_name and format");
        if (info->dimensions != std::vector<int>{2, 3})
            return fail("observer 'max_speed_csv' should work in 2D and 3D, not " + info->dimensions_text());

        spdlog::logger log("check_template");  // no sinks: quiet
        fl::Body body;
        body.reference_position = fl::planar_positions(Eigen::ArrayXd::LinSpaced(2, 0.0, 1.0), Eigen::ArrayXd::Zero(2));
        body.mass = Eigen::ArrayXd::Ones(2);
        fl::Quantities quantities;
        fl::System system(body, 0);
        Eigen::VectorXd& y = system.initial_state();
        system.layout().velocities_along(y, 0) << 3.0, 0.5;
        system.layout().velocities_along(y, 1) << 4.0, 0.5;
        const fl::StageInfo stage{"load", 0, 0.0, 1.0, true};
        fl::RunInfo run_info;
        run_info.framework_version = "0.0.0-check";
        run_info.scene_hash = "c0ffee";
        fl::Context ctx{log, 0, &body, &quantities, nullptr, "observers[0]"};
        try {  // built in code as a scene would not let it be: refused by spec().checked()
            registry.create<fl::Observer>("max_speed_csv", {{"file_name", std::string("../speed.csv")}}, ctx);
            return fail("observer 'max_speed_csv' accepts a file outside the output directory");
        } catch (const fl::InputError&) {}
        {
            auto observer =
                registry.create<fl::Observer>("max_speed_csv", {{"file_name", std::string("speed.csv")}}, ctx);
            const fl::RunView view{system, body, system.state(), quantities, stage, 7, output, run_info, log};
            observer->begin(view);
            observer->observe(view);
            observer->end(view);
        }

        std::ifstream in(output / "speed.csv");
        if (!in) return fail("no table written to " + (output / "speed.csv").string());
        std::string header, row, extra;
        std::getline(in, header);
        std::getline(in, row);
        if (header != "time,time_since_loading,step,max_speed") return fail("unexpected header '" + header + "'");
        std::istringstream fields(row);
        double t = -1, since_loading = -1, speed = -1;
        long long step = -1;
        char c1 = 0, c2 = 0, c3 = 0;
        fields >> t >> c1 >> since_loading >> c2 >> step >> c3 >> speed;
        if (!fields || c1 != ',' || c2 != ',' || c3 != ',' || t != 0.0 || since_loading != 0.0 || step != 7 ||
            std::abs(speed - 5.0) > 1e-12)
            return fail("unexpected row '" + row + "', expected 0,0,7,5");
        if (std::getline(in, extra)) return fail("more rows than observations");
        std::ifstream sidecar(output / "speed.csv.meta.yaml");
        std::stringstream provenance;
        provenance << sidecar.rdbuf();
        if (provenance.str().find("scene_hash: c0ffee") == std::string::npos)
            return fail("no provenance beside the table: '" + provenance.str() + "'");
        {  // a 3D body of two nodes: the largest speed is |(2, 3, 6)| = 7 m/s
            fl::Body solid;
            solid.reference_position = Eigen::ArrayXXd::Zero(2, 3);
            solid.reference_position(1, 0) = 1.0;
            solid.mass = Eigen::ArrayXd::Ones(2);
            solid.contact_frame = fl::ContactFrame::horizontal_base(3);
            fl::Quantities solid_quantities;
            fl::System solid_system(solid, 0);
            Eigen::VectorXd& y3 = solid_system.initial_state();
            solid_system.layout().velocities(y3) << 2.0, 0.5, 3.0, 0.5, 6.0, 0.5;
            fl::Context solid_ctx{log, 0, &solid, &solid_quantities, nullptr, "observers[0]"};
            auto observer =
                registry.create<fl::Observer>("max_speed_csv", {{"file_name", std::string("speed_3d.csv")}}, solid_ctx);
            const fl::RunView view{solid_system, solid, solid_system.state(), solid_quantities, stage, 1, output,
                                   run_info,     log};
            observer->begin(view);
            observer->observe(view);
            observer->end(view);
        }
        std::ifstream in3(output / "speed_3d.csv");
        std::string header3, row3;
        std::getline(in3, header3);
        std::getline(in3, row3);
        const double speed3 = std::stod(row3.substr(row3.rfind(',') + 1));
        if (std::abs(speed3 - 7.0) > 1e-12)
            return fail("on a 3D body: unexpected row '" + row3 + "', expected speed 7");
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    std::cout << "check_template: " << plugin.string() << " loads and writes its table\n";
    return 0;
}
