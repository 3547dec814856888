#include "frictionlab/simulation/simulation.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "frictionlab/base/version.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/hot_kernel.hpp"
#include "frictionlab/base/scene_errors.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/simulation/loading_start.hpp"
#include "frictionlab/simulation/stability.hpp"

namespace frictionlab {

namespace {
/// Where the first non-finite value of the state is, said in the physics' terms.
std::string locate_non_finite(const System& sys) {
    const StageView s = sys.state();
    for (const auto& [prefix, values] : {std::pair{"", &s.position}, std::pair{"v", &s.velocity}})
        for (int axis = 0; axis < s.dimension(); ++axis)
            for (Index i = 0; i < values->rows(); ++i)
                if (!std::isfinite((*values)(i, axis)))
                    return fmt::format("{}{} of block {} is {}", prefix, axis_name(axis, s.dimension()), i,
                                       (*values)(i, axis));
    for (Index i = 0; i < s.aux.size(); ++i)
        if (!std::isfinite(s.aux(i))) return fmt::format("auxiliary variable {} is {}", i, s.aux(i));
    return "a value is not finite";
}

/// Whether every value of y is finite: none has an all-ones exponent (NaN, infinity). Adding 1 to
/// the exponent field carries into the sign bit exactly then; integer and, add and or make one
/// vectorised pass with no branch, where allFinite() tests value by value.
FRICTIONLAB_HOT_KERNEL
bool all_finite(const double* __restrict y, Index n) {
    constexpr std::uint64_t exponent = 0x7ff0'0000'0000'0000, exponent_one = 0x0010'0000'0000'0000;
    std::uint64_t carries = 0;
    for (Index i = 0; i < n; ++i) carries |= (std::bit_cast<std::uint64_t>(y[i]) & exponent) + exponent_one;
    return (carries >> 63) == 0;
}
}  // namespace

Simulation::Simulation(const Scene& scene, const Registry& registry, spdlog::logger& log)
    : scene_(scene), registry_(registry), log_(log) {
    info_ = RunInfo{framework_version(),           scene.file, scene.hash, scene.seed, {}, scene.resolved_yaml, {},
                    loading_start(scene, registry)};
    bulk_ = located_in_scene(
        scene.bulk, [&] { return registry.create<BulkModel>(scene.bulk.type, scene.bulk.values, context("bulk")); });
    record_plugin(scene.bulk, Kind::bulk_model);
    // The scene check judged every type against the dimension the bulk model declares: it must be the body's.
    if (const int declared = registry.find(Kind::bulk_model, scene.bulk.type)->body_dimension(scene.bulk.values);
        declared != bulk_->body().dimension())
        throw InputError(fmt::format("bulk model '{}' declares {}D bodies (its spec's dimensions) but built a {}D one",
                                     scene.bulk.type, declared, bulk_->body().dimension()));

    // Every other component is built even when one refuses, so that one pass names every change the
    // scene needs (design.md: fail early, precisely, all at once).
    Diagnostics refusals;
    bool effect_refused = false;  // a refused effect publishes nothing: the fields it would have are not missing
    const auto build = [&](const ComponentSpec& c, auto make) -> decltype(make()) {
        try {
            return located_in_scene(c, make);
        } catch (const SceneErrors& e) {
            for (const auto& d : e.diagnostics().list()) refusals.error(d.where, d.key_path, d.message);
            return nullptr;
        }
    };
    struct Pending {
        std::unique_ptr<Effect> effect;
        std::vector<std::string> stages;
        std::string label;
    };
    std::vector<Pending> effects;
    for (auto& e : bulk_->effects(context("bulk"))) effects.push_back({std::move(e), {}, {}});
    // Loaders come before the friction law: it reads the normal force the base contact publishes.
    for (const auto& l : scene.loaders) {
        auto loader = build(l, [&] { return registry.create<Loader>(l.type, l.values, context(l.path)); });
        effect_refused = effect_refused || !loader;
        if (loader) effects.push_back({std::move(loader), l.stages, l.type});
        record_plugin(l, Kind::loader);
    }
    if (scene.friction) {
        const auto& f = *scene.friction;
        auto law = build(f, [&] { return registry.create<FrictionLaw>(f.type, f.values, context(f.path)); });
        effect_refused = effect_refused || !law;
        if (law) effects.push_back({std::move(law), {}, f.type});
        record_plugin(f, Kind::friction_law);
    }
    integrator_ = build(scene.integrator, [&] {
        return registry.create<Integrator>(scene.integrator.type, scene.integrator.values, context("integrator"));
    });
    record_plugin(scene.integrator, Kind::integrator);
    if (integrator_ && !integrator_->implicit_in_local_velocity())
        for (const auto& e : effects) {
            const double dt = integrator_->nominal_dt();
            if (const std::string why = e.effect->needs_implicit_velocity(); !why.empty())
                refusals.error(scene.integrator.where, "integrator",
                               fmt::format("{}, and {} steps it explicitly: use an integrator that takes it "
                                           "implicitly, integrator: {{type: imex_euler, dt: {:.3g}}}",
                                           why, scene.integrator.type, dt));
            else if (const std::string caveat = e.effect->explicit_step_caveat(dt); !caveat.empty())
                info_.caveats.push_back(fmt::format(
                    "integrator: {} steps {} explicitly: {}{}", scene.integrator.type, e.label, caveat,
                    e.effect->has_velocity_jacobian()
                        ? fmt::format("; integrator: {{type: imex_euler, dt: {:.3g}}} takes it implicitly", dt)
                        : std::string("; show what depends on it at two steps")));
        }
    // Observers last: they read what the effects publish (and choose by it, e.g. a criterion left auto).
    for (const auto& o : scene.observers) {
        observers_.push_back(build(o, [&] {
            Context c = context(o.path);
            c.effects_refused = effect_refused;
            return registry.create<Observer>(o.type, o.values, c);
        }));
        record_plugin(o, Kind::observer);
    }
    if (!effect_refused) check_needed_fields(refusals);
    if (!refusals.empty()) throw SceneErrors(refusals);
    for (const auto& c : info_.resolved_choices) log_.info("{}: {} ({})", c.key_path, c.value, c.reason);

    system_ = std::make_unique<System>(bulk_->body(), aux_.count);
    system_->use_quantities(quantities_);
    for (auto& e : effects) system_->add_effect(std::move(e.effect), std::move(e.stages), std::move(e.label));
    Eigen::VectorXd& y = system_->initial_state();
    Eigen::Ref<Eigen::ArrayXd> aux = system_->layout().aux_variables(y).array();
    system_->for_each_effect([&](const Effect& e) { e.initialise_aux(aux); });
    check_step_count();
}

void Simulation::check_step_count() const {
    const double dt = integrator_->nominal_dt();
    double steps = 0, duration = 0;
    for (const auto& stage : scene_.stages) steps += std::ceil(stage.duration / dt), duration += stage.duration;
    if (steps <= most_steps) return;
    throw SceneErrors(Diagnostic{scene_.integrator.where, "integrator",
                                 fmt::format("{:.3g} s of stages at dt = {:.3g} s is {:.3g} steps, more than the "
                                             "{:.0e} a run may take: a step or a stage duration is off by orders "
                                             "of magnitude",
                                             duration, dt, steps, most_steps)});
}

void Simulation::check_needed_fields(Diagnostics& diagnostics) const {
    // One diagnostic per reader, naming every field it misses: a reader of the junction counts
    // misses all three, for one reason and with one remedy.
    struct Missing {
        std::vector<std::string> fields;
        std::string node_set, remedy;
    };
    std::map<std::string, Missing> by_reader;
    for (const auto& u : quantities_.unpublished_fields()) {
        Missing& m = by_reader[u.reader.component];
        m.fields.push_back("'" + u.name + "'");
        m.node_set = u.node_set;
        m.remedy = u.reader.remedy;
    }
    for (const auto& [reader, m] : by_reader) {
        const ComponentSpec* c = component_at(reader);
        const std::string remedy =
            m.remedy.empty()
                ? "add the effect that publishes it (share/docs/glossary.md lists who publishes each quantity)"
                : m.remedy;
        diagnostics.error(c ? c->where : scene_.bulk.where, reader,
                          fmt::format("{} reads {} {} over node set '{}', which no effect of this scene publishes: {}",
                                      c ? c->type : reader, m.fields.size() == 1 ? "the field" : "the fields",
                                      fmt::join(m.fields, ", "), m.node_set, remedy));
    }
}

const ComponentSpec* Simulation::component_at(const std::string& path) const {
    if (scene_.friction && scene_.friction->path == path) return &*scene_.friction;
    for (const auto* list : {&scene_.loaders, &scene_.observers})
        for (const auto& c : *list)
            if (c.path == path) return &c;
    return nullptr;
}

std::vector<std::unique_ptr<Observer>> Simulation::take_observers() { return std::move(observers_); }

Simulation::~Simulation() = default;

Context Simulation::context(const std::string& name) {
    return Context{log_, scene_.seed, bulk_ ? &bulk_->body() : nullptr, &quantities_, &aux_,
                   name, &registry_,  &info_.resolved_choices};
}

void Simulation::record_plugin(const ComponentSpec& component, Kind kind) {
    const TypeInfo* t = registry_.find(kind, component.type);
    if (!t || t->library.empty()) return;
    for (const auto& p : info_.plugins)
        if (p.file == t->library) return;
    for (const auto& p : registry_.plugins())
        if (p.file == t->library) info_.plugins.push_back(p);
}

StageInfo Simulation::begin_stage(std::size_t index) {
    const StageSpec& spec = scene_.stages.at(index);
    StageInfo stage{spec.name, static_cast<int>(index), system_->time(), spec.duration, spec.friction_events};
    system_->begin_stage(stage);
    log_.info("stage {} '{}': {:.6g} s from t = {:.6g} s, friction events {}", stage.index + 1, stage.name,
              stage.duration, stage.t_start, stage.friction_events ? "on" : "off");
    for (const auto& e : system_->pipeline()) log_.info("  effect: {}", e);
    check_stability(stage);
    return stage;
}

StageInfo Simulation::resume_stage(std::size_t index, double t_start) {
    const StageSpec& spec = scene_.stages.at(index);
    StageInfo stage{spec.name, static_cast<int>(index), t_start, spec.duration, spec.friction_events};
    system_->resume_stage(stage);
    log_.info("stage {} '{}' resumed (begun at t = {:.6g} s)", stage.index + 1, stage.name, stage.t_start);
    return stage;
}

void Simulation::check_stability(const StageInfo& stage) {
    const double radius = integrator_->stability_radius(), dt = integrator_->nominal_dt();
    stable_step_note_ = fmt::format("no stable-step limit: {} chooses its own step", scene_.integrator.type);
    if (!std::isfinite(radius)) return;
    const StabilityEstimate e = estimate_stable_step(*system_, *integrator_);
    if (!std::isfinite(e.lambda_max) || !(e.dt_limit > 0)) {
        // A degenerate system (a mass of 1e-300 kg, an infinite stiffness) has no stable step to name.
        const std::string message = fmt::format(
            "stage '{}': the stable time step cannot be estimated: the linearised system's largest |eigenvalue| is "
            "{} 1/s (set by {}), so some mass is too small or some stiffness or damping too large for double "
            "precision; check the bulk's density and size and the loaders' stiffnesses",
            stage.name, e.lambda_max, e.limiting_effect.empty() ? "no single effect" : e.limiting_effect);
        if (refuse_unstable_) throw InputError(message);
        log_.warn("{}", message);
        return;
    }
    stable_step_note_ =
        fmt::format("stable step: dt <= {:.3g} s (largest |eigenvalue| {:.3g} 1/s, set by {}); dt = {:.3g} s",
                    e.dt_limit, e.lambda_max, e.limiting_effect, dt);
    log_.info("  {}", stable_step_note_);
    if (dt <= e.dt_limit) return;
    const std::string message = fmt::format(
        "stage '{}': the time step dt = {:.3g} s is above the estimated stable step {:.3g} s of the {} integrator "
        "for this system (largest |eigenvalue| {:.3g} 1/s, which times dt must stay below {:.4g}); the limit is set by "
        "{} (alone: {:.3g} 1/s). Use a smaller integrator.dt, or --allow-unstable-step to run anyway",
        stage.name, dt, e.dt_limit, scene_.integrator.type, e.lambda_max, e.lambda_max * e.dt_limit, e.limiting_effect,
        e.limiting_lambda);
    if (refuse_unstable_) throw InputError(message);
    log_.warn("{}", message);
}

double Simulation::stage_end(std::size_t index) const {
    double end = 0;
    for (std::size_t i = 0; i <= index; ++i) end += scene_.stages.at(i).duration;
    return end;
}

std::pair<double, std::size_t> Simulation::latest_load_ramp_end() const {
    std::pair<double, std::size_t> latest{-std::numeric_limits<double>::infinity(), 0};
    const std::size_t effects = system_->pipeline().size();
    for (std::size_t k = 0; k < effects; ++k) latest = std::max(latest, {system_->load_ramp_end(k), k});
    return latest;
}

std::string Simulation::cannot_end_at_rest(std::size_t index) const {
    const StageSpec& spec = scene_.stages.at(index);
    if (!std::isfinite(spec.max_speed_at_end)) return {};
    const double end = stage_end(index);
    const auto [ramp_end, effect] = latest_load_ramp_end();
    if (ramp_end < end) return {};
    return fmt::format(
        "stage '{}' must end at rest (max_speed_at_end {:g} m/s) at t = {:g} s, but the {} reaches its full "
        "value only at t = {:g} s, so the slider is still being pressed then. Make the stage last well beyond "
        "the ramp (the slider needs time to calm after it: the shipped scenes settle for 8 ms after a 2 ms "
        "ramp), or shorten the ramp",
        spec.name, spec.max_speed_at_end, end, system_->pipeline().at(effect), ramp_end);
}

double Simulation::calm_from(std::size_t index) const {
    const StageSpec& spec = scene_.stages.at(index);
    if (!std::isfinite(spec.max_speed_at_end)) return std::numeric_limits<double>::infinity();
    return std::max(stage_end(index) - 0.5 * spec.duration, latest_load_ramp_end().first);
}

double Simulation::step(double max_dt) {
    const double dt = integrator_->step(*system_, max_dt);
    if (!all_finite(system_->y().data(), system_->y().size()))
        throw RunError(fmt::format("step {}, t = {:.9g} s: {}", system_->step_index(), system_->time(),
                                   locate_non_finite(*system_)));
    // A finite but exploding state (an unstable step) is caught long before it overflows.
    if (system_->step_index() % runaway_check_interval == 0) check_bounded();
    return dt;
}

void Simulation::check_bounded() const {
    const StageView s = system_->state();
    const Body& body = system_->body();
    const double limit = runaway_factor * std::max(body.length, body.height);
    Index node = 0;
    const double dx = (s.position - body.reference_position).abs().rowwise().maxCoeff().maxCoeff(&node);
    if (dx > limit)
        throw RunError(
            fmt::format("step {}, t = {:.9g} s: block {} has moved {:.3g} m from its reference position, "
                        "more than {} times the slider size: the run is unstable (time step too large?)",
                        system_->step_index(), system_->time(), node, dx, runaway_factor));
}

bool Simulation::reached(double t_end) const {
    // Time is a sum of steps, so it may miss t_end by round-off; a millionth of a step is no step.
    return t_end - system_->time() <= 1e-6 * integrator_->nominal_dt();
}

void Simulation::advance_to(double t_end) {
    while (!reached(t_end)) step(t_end - system_->time());
}

}  // namespace frictionlab
