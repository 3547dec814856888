#pragma once
// Trivial component types for the plugin-loading tests: just enough to be registered, created and
// called across the plugin boundary.
#include <string>
#include <string_view>

#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/simulation/run.hpp"

namespace frictionlab::test {

/// Counts the states it observes and reports the count in the run's logger at the end, which shows
/// that a plugin logs into the host's logger (spdlog is shared, not header-only).
class CountingObserver final : public Observer {
public:
    struct Params {
        std::string label = "count";
    };
    static constexpr std::string_view type = "test_counting_observer";
    static ParamSpec<Params> spec() {
        ParamSpec<Params> s("Counts observed states (plugin-loading tests).");
        s.add("label", &Params::label, "Name used in the log line.");
        return s;
    }
    CountingObserver(const Params& p, const Context& ctx) : label_(p.label) {
        ctx.log.info("{}: made for {}", label_, ctx.name);
    }
    void observe(const RunView&) override { ++count_; }
    void end(const RunView& view) override { view.log.info("{}: observed {} states", label_, count_); }

private:
    std::string label_;
    long long count_ = 0;
};

/// Pushes every node along x with a constant force.
class ConstantPush final : public Loader {
public:
    struct Params {
        double force = 1.0;
    };
    static constexpr std::string_view type = "test_constant_push";
    static ParamSpec<Params> spec() {
        ParamSpec<Params> s("Constant force along x on every node (plugin-loading tests).");
        s.add("force", &Params::force, "Force on each node.").unit("N");
        return s;
    }
    ConstantPush(const Params& p, const Context&) : force_(p.force) {}
    std::string describe() const override { return "constant push"; }
    void add_forces(const StageView&, ForceView& f) override { f.fx += force_; }

private:
    double force_;
};

/// A friction law that adds no force, registered as Name::type: for the registration cases.
template <class Name>
class NoopLaw final : public FrictionLaw {
public:
    struct Params {};
    static constexpr std::string_view type = Name::type;
    static ParamSpec<Params> spec() { return ParamSpec<Params>("Adds no force (plugin-loading tests)."); }
    NoopLaw(const Params&, const Context&) {}
    std::string describe() const override { return std::string(type); }
    void add_forces(const StageView&, ForceView&) override {}
};

/// An observer that does nothing, registered as Name::type.
template <class Name>
class NoopObserver final : public Observer {
public:
    struct Params {};
    static constexpr std::string_view type = Name::type;
    static ParamSpec<Params> spec() { return ParamSpec<Params>("Observes nothing (plugin-loading tests)."); }
    NoopObserver(const Params&, const Context&) {}
    void observe(const RunView&) override {}
};

}  // namespace frictionlab::test
