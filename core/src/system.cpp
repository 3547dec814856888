#include "frictionlab/system.hpp"

#include <algorithm>

#include "frictionlab/hot_kernel.hpp"

namespace frictionlab {

namespace {
/// f *= inverse_mass, node by node.
FRICTIONLAB_HOT_KERNEL
void scale(double* __restrict f, const double* __restrict inverse_mass, Index n) {
    for (Index i = 0; i < n; ++i) f[i] *= inverse_mass[i];
}
}  // namespace

System::System(const Body& body, Index aux_size)
    : body_(body), layout_{body.size(), aux_size}, inverse_mass_(body.mass.inverse()) {
    const Index n = layout_.nodes;
    y_ = Eigen::VectorXd::Zero(layout_.size());
    y_.segment(0, n) = body.x0.matrix();
    y_.segment(n, n) = body.z0.matrix();
    scratch_ = Eigen::VectorXd::Zero(layout_.size());
    net_force_ = Eigen::VectorXd::Zero(2 * n);
}

void System::add_effect(std::unique_ptr<Effect> effect, std::vector<std::string> active_in, std::string label) {
    if (label.empty()) label = effect->key();
    if (label.empty()) label = "effect_" + std::to_string(slots_.size());
    const std::string base = label;
    for (int n = 2; std::find(labels_.begin(), labels_.end(), label) != labels_.end(); ++n)
        label = base + "_" + std::to_string(n);
    labels_.push_back(std::move(label));
    slots_.push_back({std::move(effect), std::move(active_in), true});
    active_.push_back(slots_.back().effect.get());
    active_slot_.push_back(slots_.size() - 1);
    if (work_accounting()) work_.push_back(0), pending_work_.push_back(0);
    plan_evaluations();
}

void System::plan_evaluations() {
    plan_.clear();
    for (std::size_t k = 0; k < active_.size(); ++k) {
        const bool fused = k + 1 < active_.size() && active_[k]->fuses_with(*active_[k + 1]);
        plan_.push_back({k, fused});
        if (fused) ++k;
    }
}

void System::enable_work_accounting() {
    work_.assign(slots_.size(), 0.0);
    pending_work_.assign(slots_.size(), 0.0);
    effect_force_ = Eigen::VectorXd::Zero(layout_.size());
}

void System::derivative(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy, double work_weight) {
    evaluate(t, y, dy, work_weight);
    ++evaluations_;
}

void System::evaluate(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy, double work_weight) {
    const Index n = layout_.nodes;
    dy.head(2 * n) = y.segment(2 * n, 2 * n);
    compute_accelerations(t, y, dy.tail(layout_.size() - 2 * n), work_weight);
}

void System::accelerations(double t, const Eigen::VectorXd& y, Eigen::Ref<Eigen::VectorXd> a, double work_weight) {
    compute_accelerations(t, y, a, work_weight);
    ++evaluations_;
}

void System::forces(double t, const Eigen::VectorXd& y, Eigen::Ref<Eigen::VectorXd> f, double work_weight) {
    compute_forces(t, y, f, work_weight);
    ++evaluations_;
}

void System::compute_accelerations(double t, const Eigen::VectorXd& y, Eigen::Ref<Eigen::VectorXd> a,
                                   double work_weight) {
    compute_forces(t, y, a, work_weight);
    ForceView f = forces_at(a.data(), layout_);
    divide_by_mass(f);
}

void System::compute_forces(double t, const Eigen::VectorXd& y, Eigen::Ref<Eigen::VectorXd> a, double work_weight) {
    // The first evaluation writes the forces (Effect::set_forces_with): only the aux rates need zeros.
    const Index n = layout_.nodes;
    if (plan_.empty()) a.setZero();
    else a.tail(a.size() - 2 * n).setZero();
    const StageView s = view_of(y, layout_, t);
    ForceView f = forces_at(a.data(), layout_);
    const bool accounting = work_accounting() && work_weight != 0;
    for (const Evaluation& e : plan_) {
        if (accounting)
            for (std::size_t k = e.first; k <= e.first + e.fused; ++k) add_work(k, s, work_weight);
        Effect* next = e.fused ? active_[e.first + 1] : nullptr;
        if (&e == &plan_.front()) active_[e.first]->set_forces_with(next, s, f);
        else if (next) active_[e.first]->add_forces_with(*next, s, f);
        else active_[e.first]->add_forces(s, f);
    }
}

void System::add_work(std::size_t active_index, const StageView& s, double weight) {
    // The effect alone into a scratch vector, to know its power F_e . v at this stage. The forces
    // that move the state are summed apart, as without accounting, so accounting changes no result.
    const Index n = layout_.nodes;
    effect_force_.tail(layout_.size() - 2 * n).setZero();
    ForceView fe = forces_of(effect_force_, layout_);
    active_[active_index]->add_forces(s, fe);
    const Eigen::Map<const Eigen::VectorXd> velocity(s.vx.data(), 2 * n);  // [vx | vz]
    pending_work_[active_slot_[active_index]] += weight * effect_force_.segment(2 * n, 2 * n).dot(velocity);
}

void System::effect_derivative(std::size_t active_index, double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
    const Index n = layout_.nodes;
    dy.head(2 * n) = y.segment(2 * n, 2 * n);
    dy.tail(layout_.size() - 2 * n).setZero();
    ForceView f = forces_of(dy, layout_);
    active_.at(active_index)->add_forces(view_of(y, layout_, t), f);
    divide_by_mass(f);
}

void System::divide_by_mass(ForceView& f) const {
    scale(f.fx.data(), inverse_mass_.data(), layout_.nodes);
    scale(f.fz.data(), inverse_mass_.data(), layout_.nodes);
}

bool System::local_velocity_forces(double t, const Eigen::VectorXd& y, Eigen::ArrayXd& fx, Eigen::ArrayXd& dfx_dvx) {
    const Index n = layout_.nodes;
    fx.setZero(n);
    dfx_dvx.setZero(n);
    if (local_scratch_.size() != layout_.size()) local_scratch_.resize(layout_.size());
    local_scratch_.setZero();
    const StageView s = view_of(y, layout_, t);
    ForceView f = forces_of(local_scratch_, layout_);
    bool any = false;
    for (Effect* e : active_) {
        if (!e->has_velocity_jacobian()) continue;
        any = true;
        e->add_forces(s, f);
        e->add_velocity_jacobian(s, dfx_dvx);
    }
    fx = f.fx;
    return any;
}

void System::begin_step() {
    std::fill(pending_work_.begin(), pending_work_.end(), 0.0);
    const StageView s = state();
    for (Effect* e : active_) e->begin_step(s);
}

void System::accept(double t, const Eigen::VectorXd& y) {
    y_ = y;
    commit_step(t);
}

void System::accept_swap(double t, Eigen::VectorXd& y) {
    y_.swap(y);
    commit_step(t);
}

void System::commit_step(double t) {
    const double dt = t - t_;
    t_ = t;
    ++steps_;
    for (std::size_t k = 0; k < work_.size(); ++k) work_[k] += pending_work_[k];
    const StageView s = state();
    for (Effect* e : active_) e->commit(s, dt);
}

double System::next_event_time() const {
    double next = std::numeric_limits<double>::infinity();
    for (const Effect* e : active_) next = std::min(next, e->next_event_time());
    return next;
}

bool System::quasi_static_regime(const StageView& s) const {
    for (const Effect* e : active_)
        if (!e->quasi_static_regime(s)) return false;
    return true;
}

void System::assemble_stiffness(const StageView& s, Eigen::SparseMatrix<double>& stiffness) {
    triplets_.clear();
    for (const Effect* e : active_) e->add_stiffness(s, triplets_);
    const Index dof = 2 * layout_.nodes;
    stiffness.resize(dof, dof);
    stiffness.setFromTriplets(triplets_.begin(), triplets_.end());
}

double System::foreseen_event_time(const StageView& s) const {
    double next = std::numeric_limits<double>::infinity();
    for (const Effect* e : active_) next = std::min(next, e->foreseen_event_time(s));
    return next;
}

void System::add_straight_path_work(double t1, const Eigen::VectorXd& y1) {
    if (!work_accounting()) return;
    const Index n = layout_.nodes;
    const double h = t1 - t_;
    if (!(h > 0)) return;
    path_state_ = y_;
    path_state_.segment(2 * n, 2 * n) = (y1.head(2 * n) - y_.head(2 * n)) / h;
    for (std::size_t k = 0; k < active_.size(); ++k) add_work(k, view_of(path_state_, layout_, t_), h / 2);
    path_state_.head(2 * n) = y1.head(2 * n);
    path_state_.tail(layout_.aux) = y1.tail(layout_.aux);
    for (std::size_t k = 0; k < active_.size(); ++k) add_work(k, view_of(path_state_, layout_, t1), h / 2);
}

void System::begin_stage(const StageInfo& stage) {
    active_.clear();
    active_slot_.clear();
    for (std::size_t k = 0; k < slots_.size(); ++k) {
        Slot& slot = slots_[k];
        slot.active = slot.active_in.empty() ||
                      std::find(slot.active_in.begin(), slot.active_in.end(), stage.name) != slot.active_in.end();
        if (slot.active) active_.push_back(slot.effect.get()), active_slot_.push_back(k);
    }
    plan_evaluations();
    const StageView s = state();
    for (Effect* e : active_) e->begin_stage(stage, s);
}

void System::refresh() {
    evaluate(t_, y_, scratch_, 0);
    const Index n = layout_.nodes;
    net_force_.head(n) = (scratch_.segment(2 * n, n).array() * body_.mass).matrix();
    net_force_.tail(n) = (scratch_.segment(3 * n, n).array() * body_.mass).matrix();
}

std::vector<std::string> System::pipeline() const {
    std::vector<std::string> names;
    for (const Effect* e : active_) names.push_back(e->describe());
    return names;
}

}  // namespace frictionlab
