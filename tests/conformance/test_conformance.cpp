// Conformance of every type in the build's plugin directory, by kind:
//  - every type and key is documented (doc; a unit for every number) and `frictionlab example` of
//    every type is itself a valid scene component;
//  - every friction law resists a small forward displacement and velocity of a loaded, stuck
//    interface with a finite force, publishes friction_force, and is deterministic for a seed;
//  - every bulk model provides the standard node sets and feels no force under rigid translation;
//  - every type refuses Params built in code that a scene could not give (spec().checked).
#include <cmath>
#include <optional>
#include <sstream>

#include <gtest/gtest.h>
#include <spdlog/logger.h>
#include <spdlog/spdlog.h>

#include "frictionlab/plugins/search.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/scene/scene.hpp"
#include "frictionlab/simulation/system.hpp"

namespace frictionlab {
namespace {

constexpr Kind all_kinds[] = {Kind::bulk_model, Kind::friction_law, Kind::loader, Kind::integrator, Kind::observer};

Registry& shipped() {
    static Registry registry;
    static const bool loaded = (load_plugins(registry, {FRICTIONLAB_PLUGIN_DIR}, *spdlog::default_logger()), true);
    (void)loaded;
    return registry;
}

ParamValues defaults(const TypeInfo& t) {
    ParamValues v;
    for (const auto& p : t.params) v[p.key] = p.default_value;
    return v;
}

TEST(Conformance, EveryTypeAndKeyIsDocumented) {
    for (Kind kind : all_kinds)
        for (const TypeInfo* t : shipped().types(kind)) {
            EXPECT_FALSE(t->summary.empty()) << t->type;
            for (const auto& p : t->params) {
                EXPECT_FALSE(p.doc.empty()) << t->type << "." << p.key;
                if (p.type == ValueType::real || p.type == ValueType::real_list) {
                    EXPECT_FALSE(p.unit.empty()) << t->type << "." << p.key << " is a number without a unit";
                }
            }
        }
    EXPECT_GE(shipped().types(Kind::friction_law).size(), 5u);
}

/// `snippet` placed as the scene's component of its kind, in an otherwise minimal valid scene.
std::string scene_with(Kind kind, const std::string& snippet) {
    std::string indented;
    std::istringstream lines(snippet);
    for (std::string line; std::getline(lines, line);) indented += "    " + line + "\n";
    const auto section = [&](Kind k, const std::string& fallback) {
        if (k != kind) return fallback;
        const bool list = k == Kind::loader || k == Kind::observer;
        return std::string(to_string(k) == "bulk_model" ? "bulk"
                           : k == Kind::friction_law    ? "friction"
                           : k == Kind::loader          ? "loaders"
                           : k == Kind::observer        ? "observers"
                                                        : "integrator") +
               ":\n" + (list ? "  -\n" : "") + indented;
    };
    return "output: out\n" + section(Kind::bulk_model, "bulk: {type: spring_lattice_2d}\n") +
           section(Kind::friction_law, "") + section(Kind::loader, "") +
           section(Kind::integrator, "integrator: {type: rk4}\n") + section(Kind::observer, "") +
           "stages:\n  - {name: load, duration: 1.0e-3}\n";
}

TEST(Conformance, EveryExampleIsAValidComponent) {
    for (Kind kind : all_kinds)
        for (const TypeInfo* t : shipped().types(kind)) {
            const std::string text = scene_with(kind, example_yaml(*t));
            Diagnostics d;
            auto document = SceneDocument::parse(text, "example", {}, d);
            document.validate(shipped(), d);
            EXPECT_TRUE(d.empty()) << to_string(kind) << "/" << t->type << ":\n" << d.format() << "\n" << text;
        }
}

/// A small lattice whose interface carries 10 N per block, stuck, then nudged forward.
class FrictionLawProbe {
public:
    FrictionLawProbe(const TypeInfo& law, std::uint64_t seed) {
        ParamValues lattice = defaults(*shipped().find(Kind::bulk_model, "spring_lattice_2d"));
        lattice["nx"] = std::int64_t{11}, lattice["nz"] = std::int64_t{3};
        lattice["length"] = 0.025, lattice["height"] = 0.005;
        bulk_ = shipped().create<BulkModel>("spring_lattice_2d", lattice, context(seed, nullptr));
        const Body& body = bulk_->body();
        const auto n = static_cast<Index>(body.nodes("interface").size());
        quantities_.field("normal_force", "interface", n, "N", "test") = Eigen::ArrayXd::Constant(n, 10.0);
        auto effect = shipped().create<FrictionLaw>(law.type, defaults(law), context(seed, &body));
        system_ = std::make_unique<System>(body, aux_.count);
        system_->add_effect(std::move(effect));
        Eigen::Ref<Eigen::ArrayXd> aux = system_->layout().aux_variables(system_->initial_state()).array();
        system_->for_each_effect([&](const Effect& e) { e.initialise_aux(aux); });
        // Settle: a few commits at rest, so laws whose contacts follow the normal force form them.
        system_->begin_stage({"settle", 0, 0.0, 1e-5, false});
        for (int k = 1; k <= 10; ++k) system_->begin_step(), system_->accept(k * 1e-6, system_->y());
        system_->begin_stage({"load", 1, system_->time(), 1.0, true});
    }

    /// x-forces on the interface nodes with every interface node displaced by dx and moving at v.
    Eigen::ArrayXd interface_force(double dx, double v) {
        const Body& body = bulk_->body();
        const auto& nodes = body.nodes("interface");
        const StateLayout& l = system_->layout();
        Eigen::VectorXd y = system_->y(), dy(y.size());
        for (Index node : nodes) y(l.position_index(node, 0)) += dx, y(l.velocity_index(node, 0)) = v;
        system_->begin_step();
        derivative(*system_, system_->time(), y, dy);
        // The lattice is not in the pipeline, so the force on an interface node is the law's alone.
        Eigen::ArrayXd f(static_cast<Index>(nodes.size()));
        for (std::size_t k = 0; k < nodes.size(); ++k)
            f(static_cast<Index>(k)) = dy(l.velocity_index(nodes[k], 0)) * body.mass(nodes[k]);
        return f;
    }
    const Quantities& quantities() const { return quantities_; }

private:
    Context context(std::uint64_t seed, const Body* body) {
        return Context{log_, seed, body, &quantities_, &aux_, "friction"};
    }
    spdlog::logger log_{"test"};
    Quantities quantities_;
    AuxAllocator aux_;
    std::unique_ptr<BulkModel> bulk_;
    std::unique_ptr<System> system_;
};

TEST(Conformance, EveryFrictionLawResistsForwardMotionOfAStuckInterface) {
    ASSERT_GE(shipped().types(Kind::friction_law).size(), 5u);
    for (const TypeInfo* law : shipped().types(Kind::friction_law)) {
        SCOPED_TRACE(law->type);
        FrictionLawProbe probe(*law, 7);
        EXPECT_NE(probe.quantities().find_field("friction_force"), nullptr) << law->type;
        for (double dx : {1e-9, 1e-8, 1e-7})
            for (double v : {1e-6, 1e-4}) {
                const Eigen::ArrayXd f = probe.interface_force(dx, v);
                EXPECT_TRUE(f.allFinite()) << law->type;
                EXPECT_TRUE((f <= 0).all()) << law->type << ": a block pushed forward must be held back, dx = " << dx
                                            << ", v = " << v << ", f = " << f.transpose();
                EXPECT_LT(f.sum(), 0) << law->type << " gives no resistance at dx = " << dx << ", v = " << v;
            }
    }
}

TEST(Conformance, EveryFrictionLawIsDeterministicForASeed) {
    for (const TypeInfo* law : shipped().types(Kind::friction_law)) {
        FrictionLawProbe a(*law, 11), b(*law, 11);
        for (double dx : {1e-8, 1e-6})
            EXPECT_TRUE((a.interface_force(dx, 1e-5) == b.interface_force(dx, 1e-5)).all()) << law->type;
    }
}

TEST(Conformance, EveryBulkModelHasTheStandardNodeSetsAndNoForceUnderTranslation) {
    spdlog::logger log("test");
    for (const TypeInfo* t : shipped().types(Kind::bulk_model)) {
        Quantities q;
        AuxAllocator aux;
        Context ctx{log, 0, nullptr, &q, &aux, "bulk"};
        auto bulk = shipped().create<BulkModel>(t->type, defaults(*t), ctx);
        const Body& body = bulk->body();
        for (const char* set : {"all", "top", "interface", "trailing_edge", "leading_edge"})
            EXPECT_FALSE(body.nodes(set).empty()) << t->type << " node set " << set;
        EXPECT_TRUE((body.mass > 0).all()) << t->type;
        EXPECT_GT(body.bond_stiffness, 0) << t->type;
        Context with_body{log, 0, &body, &q, &aux, "bulk"};
        System system(body, aux.count);
        for (auto& e : bulk->effects(with_body)) system.add_effect(std::move(e));
        Eigen::VectorXd y = system.y(), dy(y.size());
        const StateLayout& l = system.layout();
        constexpr double shift[] = {1e-3, -2e-4, 5e-4};  // a rigid translation, at rest
        for (int axis = 0; axis < l.dimension; ++axis) l.positions_along(y, axis).array() += shift[axis];
        derivative(system, 0, y, dy);
        const double scale = body.bond_stiffness * body.spacing;
        const Eigen::ArrayXd force = l.velocities(dy).array() * body.mass.replicate(l.dimension, 1);
        EXPECT_LT(force.abs().maxCoeff(), 1e-9 * scale) << t->type;
    }
}

/// A value of `p` outside its bounds, or an item outside its items' choices; nothing where it has
/// neither (an enumeration's member only ever holds one of its named values).
std::optional<ParamValue> violating(const ParamInfo& p) {
    if (p.type == ValueType::string_list && !p.choices.empty())
        return ParamValue(std::vector<std::string>{"none_of_them"});
    if (p.type != ValueType::real && p.type != ValueType::integer && p.type != ValueType::real_list)
        return std::nullopt;
    std::optional<double> v;
    if (p.greater_than)
        v = *p.greater_than;
    else if (p.at_least)
        v = *p.at_least - 1;
    else if (p.less_than)
        v = *p.less_than;
    else if (p.at_most)
        v = *p.at_most + 1;
    if (!v) return std::nullopt;
    if (p.type == ValueType::integer) return ParamValue(static_cast<std::int64_t>(std::floor(*v)));
    if (p.type == ValueType::real_list) return ParamValue(std::vector<double>{*v});
    return ParamValue(*v);
}

TEST(Conformance, EveryTypeRefusesParamsBuiltInCodeThatASceneCouldNotGive) {
    // Built as a test or another component builds them, without a scene's validation: each key out
    // of its bounds alone is refused by the constructor, by that key, before anything is built.
    spdlog::logger log("test");
    ParamValues lattice = defaults(*shipped().find(Kind::bulk_model, "spring_lattice_2d"));
    lattice["nx"] = std::int64_t{11}, lattice["nz"] = std::int64_t{3};
    Quantities bulk_quantities;
    AuxAllocator bulk_aux;
    const auto bulk = shipped().create<BulkModel>("spring_lattice_2d", lattice,
                                                  Context{log, 0, nullptr, &bulk_quantities, &bulk_aux, "bulk"});
    int refused = 0;
    for (Kind kind : all_kinds)
        for (const TypeInfo* t : shipped().types(kind))
            for (const ParamInfo& p : t->params) {
                const auto bad = violating(p);
                if (!bad) continue;
                ParamValues values = defaults(*t);
                values[p.key] = *bad;
                Quantities q;
                AuxAllocator aux;
                const Context ctx{log, 0, &bulk->body(), &q, &aux, "probe", &shipped()};
                try {
                    (void)t->create(values, ctx);
                    ADD_FAILURE() << t->type << " accepts " << p.key << " = " << to_string(*bad);
                } catch (const InputError& e) {
                    EXPECT_EQ(std::string(e.what()).rfind(p.key + " ", 0), 0u) << t->type << ": " << e.what();
                    ++refused;
                }
            }
    EXPECT_GT(refused, 40);
}

}  // namespace
}  // namespace frictionlab
