#include "test_scene_types.hpp"

#include <fmt/format.h>

#include "frictionlab/model/kinds.hpp"

namespace frictionlab::testing {

namespace {

class FakeLattice final : public BulkModel {
public:
    struct Params {
        int nx = 41;
        int nz = 9;
        double spacing = 1e-3;
        double density = 1200;
        enum class Geometry { geometric, linear };
        Geometry geometry = Geometry::geometric;
        bool periodic = false;
    };
    static constexpr std::string_view type = "fake_lattice";
    static ParamSpec<Params> spec() {
        ParamSpec<Params> s("A lattice that is never built.\nSecond line of the summary.");
        s.add("nx", &Params::nx, "Nodes along x.").at_least(2);
        s.add("nz", &Params::nz, "Nodes along z.").greater_than(0).at_most(1000);
        s.add("spacing", &Params::spacing, "Rest length of a spring.").unit("m").greater_than(0);
        s.add("density", &Params::density, "Mass density.").unit("kg/m^3").greater_than(0);
        s.choice("geometry", &Params::geometry,
                 {{"geometric", Params::Geometry::geometric}, {"linear", Params::Geometry::linear}}, "Spring model.");
        s.add("periodic", &Params::periodic, "Periodic along x.");
        return s;
    }
    FakeLattice(const Params&, const Context&) {}
    const Body& body() const override { return body_; }
    std::vector<std::unique_ptr<Effect>> effects(const Context&) override { return {}; }

private:
    Body body_;
};

/// A body in 2D or 3D, as its `dimension` says (ParamSpec::body_dimension).
class FakeBlock final : public BulkModel {
public:
    struct Params {
        int dimension = 2;
    };
    static constexpr std::string_view type = "fake_block";
    static ParamSpec<Params> spec() {
        ParamSpec<Params> s("A block in 2D or 3D that is never built.");
        s.add("dimension", &Params::dimension, "Spatial dimension.").at_least(2).at_most(3);
        s.dimensions({2, 3});
        s.body_dimension([](const Params& p) { return p.dimension; });
        return s;
    }
    FakeBlock(const Params&, const Context&) {}
    const Body& body() const override { return body_; }
    std::vector<std::unique_ptr<Effect>> effects(const Context&) override { return {}; }

private:
    Body body_;
};

class FakeEffect : public FrictionLaw {
public:
    std::string describe() const override { return "fake"; }
    void add_forces(const StageView&, ForceView&) override {}
};

class FakeJunctions final : public FakeEffect {
public:
    struct Params {
        double mu_s = 0.7;
        double mu_d = 0.35;
        std::vector<double> weights = {1.0, 0.5};
        enum class StateModel { two_state, three_state };
        StateModel state_model = StateModel::three_state;
    };
    static constexpr std::string_view type = "fake_junctions";
    static ParamSpec<Params> spec() {
        ParamSpec<Params> s("Junctions that never slip.");
        s.add("mu_s", &Params::mu_s, "Static coefficient.").unit("1").greater_than(0);
        s.add("mu_d", &Params::mu_d, "Dynamic coefficient.").unit("1").at_least(0).also_known_as("mu_k");
        s.add("weights", &Params::weights, "Weights of the junction classes.").at_least(0).less_than(10);
        s.choice("state_model", &Params::state_model,
                 {{"two_state", Params::StateModel::two_state}, {"three_state", Params::StateModel::three_state}},
                 "Junction states.");
        s.rule("mu_d", [](const Params& p) {
            return p.mu_d <= p.mu_s ? std::string()
                                    : fmt::format("must not exceed mu_s = {:g}, got {:g}", p.mu_s, p.mu_d);
        });
        return s;
    }
    FakeJunctions(const Params&, const Context&) {}
};

class Coulomb final : public FakeEffect {
public:
    struct Params {
        double mu = 0.5;
    };
    static constexpr std::string_view type = "coulomb";
    static ParamSpec<Params> spec() {
        ParamSpec<Params> s("Coulomb friction.");
        s.add("mu", &Params::mu, "Friction coefficient.").unit("1").at_least(0);
        s.dimensions({2, 3});
        return s;
    }
    Coulomb(const Params&, const Context&) {}
};

class FakeLoader : public Loader {
public:
    std::string describe() const override { return "fake"; }
    void add_forces(const StageView&, ForceView&) override {}
};

class FakeNormalLoad final : public FakeLoader {
public:
    struct Params {
        double total_force = 400;
        std::string node_set = "top";
        double ramp_time = 0;
    };
    static constexpr std::string_view type = "fake_normal_load";
    static ParamSpec<Params> spec() {
        ParamSpec<Params> s("Pushes down on a node set.");
        s.add("total_force", &Params::total_force, "Sum of the forces.").unit("N").greater_than(0).required();
        s.add("node_set", &Params::node_set, "Nodes pushed.");
        s.add("ramp_time", &Params::ramp_time, "Time to reach the full force.").unit("s").at_least(0);
        s.dimensions({2, 3});
        return s;
    }
    FakeNormalLoad(const Params&, const Context&) {}
};

class FakeDriver final : public FakeLoader {
public:
    struct Params {
        double velocity = 1e-4;
        double stiffness = 4e6;
        std::vector<std::string> sets = {"trailing_edge"};
    };
    static constexpr std::string_view type = "fake_driver";
    static ParamSpec<Params> spec() {
        ParamSpec<Params> s("Drives a node set through a spring.");
        s.add("velocity", &Params::velocity, "Speed of the driver.").unit("m/s");
        s.add("stiffness", &Params::stiffness, "Spring constant.").unit("N/m").greater_than(0);
        s.add("sets", &Params::sets, "Node sets driven.").items_one_of({"top", "trailing_edge", "leading_edge"});
        s.dimensions({2}, "pulls a column of nodes");
        return s;
    }
    FakeDriver(const Params&, const Context&) {}
};

class FakeRk4 final : public Integrator {
public:
    struct Params {
        double dt = 2e-7;
    };
    static constexpr std::string_view type = "fake_rk4";
    static ParamSpec<Params> spec() {
        ParamSpec<Params> s("Fixed-step fourth-order Runge-Kutta.");
        s.add("dt", &Params::dt, "Time step.").unit("s").greater_than(0);
        s.dimensions({2, 3});
        return s;
    }
    FakeRk4(const Params&, const Context&) {}
    double step(System&, double max_dt) override { return max_dt; }
    double nominal_dt() const override { return 0; }
};

class FakeCurve final : public Observer {
public:
    struct Params {
        std::string file = "curve.csv";
        std::vector<std::string> columns;
        std::int64_t precision = 8;
    };
    static constexpr std::string_view type = "fake_curve";
    static ParamSpec<Params> spec() {
        ParamSpec<Params> s("Writes a loading curve.");
        s.add("file", &Params::file, "CSV file in the output folder.");
        s.add("columns", &Params::columns, "Extra columns.");
        s.add("precision", &Params::precision, "Significant digits.").at_least(1).at_most(17);
        return s;
    }
    FakeCurve(const Params&, const Context&) {}
    void observe(const RunView&) override {}
};

/// Writes a folder <prefix>/ and a collection <prefix>.pvd, declared for the scene's name check.
class FakeSeries final : public Observer {
public:
    struct Params {
        std::string prefix = "snapshots";
    };
    static constexpr std::string_view type = "fake_series";
    static ParamSpec<Params> spec() {
        ParamSpec<Params> s("Writes snapshots.");
        s.add("prefix", &Params::prefix, "Name of the folder and the collection.");
        s.writes([](const Params& p) {
            return std::vector<OutputName>{{"prefix", p.prefix}, {"prefix", p.prefix + ".pvd"}};
        });
        return s;
    }
    FakeSeries(const Params&, const Context&) {}
    void observe(const RunView&) override {}
};

}  // namespace

void register_scene_test_types(Registry& registry) {
    registry.add<FakeLattice>();
    registry.add<FakeBlock>();
    registry.add<FakeJunctions>();
    registry.add<Coulomb>();
    registry.add<FakeNormalLoad>();
    registry.add<FakeDriver>();
    registry.add<FakeRk4>();
    registry.add<FakeCurve>();
    registry.add<FakeSeries>();
}

std::string good_scene_text() {
    return R"(title: "Good scene"
seed: 42
output: out/good
bulk:
  type: fake_lattice
  nx: 21
  spacing: 1.0e-3
friction:
  type: fake_junctions
  mu_s: 0.8
loaders:
  - type: fake_normal_load
    stages: [settle, load]
    total_force: 400
  - type: fake_driver
    stages: [load]
    velocity: 2e-4
integrator:
  type: fake_rk4
  dt: 1
stages:
  - name: settle
    duration: 0.01
    friction_events: false
    max_speed_at_end: 1.0e-6
  - name: load
    duration: 4
observers:
  - type: fake_curve
    every: 1.0e-4
)";
}

}  // namespace frictionlab::testing
