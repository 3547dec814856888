#include "frictionlab/simulation/system.hpp"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/hot_kernel.hpp"
#include "frictionlab/base/parallel_chunks.hpp"
#include "frictionlab/base/state_archive.hpp"

namespace frictionlab {

namespace {
/// f *= inverse_mass, node by node.
FRICTIONLAB_HOT_KERNEL
void scale(double* __restrict f, const double* __restrict inverse_mass, Index n) {
    for (Index i = 0; i < n; ++i) f[i] *= inverse_mass[i];
}
}  // namespace

namespace {
const Body& checked(const Body& body) {
    if (const std::string problem = body.contact_frame.problem(body.dimension()); !problem.empty())
        throw InputError(fmt::format("the bulk model's body has {} axes, and {}", body.dimension(), problem));
    return body;
}
}  // namespace

System::System(const Body& body, Index aux_size)
    : body_(checked(body)), layout_(body.size(), body.dimension(), aux_size), inverse_mass_(body.mass.inverse()) {
    y_ = Eigen::VectorXd::Zero(layout_.size());
    layout_.positions(y_) = body.reference_position.reshaped().matrix();
    scratch_ = Eigen::VectorXd::Zero(layout_.size());
    net_force_ = Eigen::ArrayXXd::Zero(layout_.nodes, layout_.dimension);
}

void System::add_effect(std::unique_ptr<Effect> effect, std::vector<std::string> active_in, std::string label) {
    std::vector<Effect*> parts = effect->parts();
    if (parts.empty())
        parts = {effect.get()};
    else
        label.clear();  // each part is labelled by its own key
    for (std::size_t k = 0; k < parts.size(); ++k) {
        std::string name = label.empty() ? parts[k]->key() : label;
        if (name.empty()) name = "effect_" + std::to_string(parts_.size() + k);
        const std::string base = name;
        for (int n = 2; std::find(labels_.begin(), labels_.end(), name) != labels_.end(); ++n)
            name = base + "_" + std::to_string(n);
        labels_.push_back(std::move(name));
        if (work_accounting()) work_.push_back(0), pending_work_.push_back(0);
    }
    slots_.push_back({std::move(effect), std::move(active_in), parts_.size(), parts.size()});
    parts_.insert(parts_.end(), parts.begin(), parts.end());
    activate(nullptr);
}

void System::enable_work_accounting() {
    work_.assign(parts_.size(), 0.0);
    pending_work_.assign(parts_.size(), 0.0);
    effect_force_ = Eigen::VectorXd::Zero(layout_.size());
}

void System::add_forces(double t, const Eigen::VectorXd& y, Eigen::Ref<Eigen::VectorXd> f, const Evaluation& how) {
    shown_ = false;  // the effects publish this evaluation's quantities
    const StageView s = view_of(y, layout_, t);
    ForceView forces = forces_at(f.data(), layout_);
    const bool accounting = work_accounting() && how.work_weight != 0;
    const auto add = [&](Effect& e) { how.loaded ? e.add_loaded_forces(s, forces) : e.add_forces(s, forces); };
    if (how.part) {
        const std::size_t k = active_parts_.at(*how.part);
        if (accounting) add_work(k, s, how.work_weight);
        add(*parts_[k]);
    } else {
        for (const Slot* slot : active_) {
            if (accounting)
                for (std::size_t k = slot->first_part; k < slot->first_part + slot->part_count; ++k)
                    add_work(k, s, how.work_weight);
            add(*slot->effect);
        }
    }
    if (how.counted) ++evaluations_;
}

void System::add_work(std::size_t part, const StageView& s, double weight) {
    // The part alone into a scratch vector, to know its power F_e . v at this stage. The forces
    // that move the state are summed apart, as without accounting, so accounting changes no result.
    layout_.after_positions(effect_force_).setZero();
    ForceView fe = forces_of(effect_force_, layout_);
    parts_[part]->add_forces(s, fe);
    const Eigen::Map<const Eigen::VectorXd> velocity(s.velocity.data(), layout_.dof());
    pending_work_[part] += weight * layout_.velocities(effect_force_).dot(velocity);
}

bool System::local_velocity_forces(double t, const Eigen::VectorXd& y, Eigen::ArrayXd& force,
                                   LocalVelocityJacobian& jacobian) {
    const Index n = layout_.nodes;
    const std::vector<int>& axes = body_.contact_frame.tangential;
    jacobian.reset(n, static_cast<Index>(axes.size()));
    if (local_scratch_.size() != layout_.size()) local_scratch_.resize(layout_.size());
    local_scratch_.setZero();
    shown_ = false;
    const StageView s = view_of(y, layout_, t);
    ForceView f = forces_of(local_scratch_, layout_);
    bool any = false;
    for (const std::size_t k : active_parts_) {
        Effect* e = parts_[k];
        if (!e->has_velocity_jacobian()) continue;
        any = true;
        e->add_forces(s, f);
        e->add_velocity_jacobian(s, jacobian);
    }
    force = f.forces_along(axes[0]) * jacobian.direction.col(0);
    for (std::size_t a = 1; a < axes.size(); ++a)
        force += f.forces_along(axes[a]) * jacobian.direction.col(static_cast<Index>(a));
    return any;
}

void System::begin_step() {
    std::fill(pending_work_.begin(), pending_work_.end(), 0.0);
    const StageView s = state();
    for (const Slot* slot : active_) slot->effect->begin_step(s);
}

void System::accept(double t, const Eigen::VectorXd& y) {
    y_ = y;
    path_.open = false;
    shown_ = false;
    commit_step(t);
}

void System::begin_straight_path(double t1, const Eigen::VectorXd& y1) {
    path_.start_time = t_, path_.end_time = t1;
    evaluate_shown(t1, y1);
    path_.end_force = net_force_;
    if (quantities_) quantities_->copy_to(path_.end);
    evaluate_shown(t_, y_);  // last, so that what is shown describes the accepted state
    path_.start_force = net_force_;
    if (quantities_) quantities_->copy_to(path_.start);
    path_.open = shown_ = true;
}

void System::move_along_path(double t, const Eigen::VectorXd& y) {
    add_straight_path_work(t, y);
    for (std::size_t k = 0; k < work_.size(); ++k) work_[k] += std::exchange(pending_work_[k], 0.0);
    y_ = y;
    t_ = t;
    const double w = (t - path_.start_time) / (path_.end_time - path_.start_time);
    net_force_ = (1 - w) * path_.start_force + w * path_.end_force;
    if (quantities_) quantities_->set_between(path_.start, path_.end, w);
    shown_ = true;
}

void System::commit_step(double t) {
    const double dt = t - t_;
    t_ = t;
    ++steps_;
    for (std::size_t k = 0; k < work_.size(); ++k) work_[k] += pending_work_[k];
    const StageView s = state();
    for (const Slot* slot : active_) slot->effect->commit(s, dt);
}

double System::next_event_time() const {
    double next = std::numeric_limits<double>::infinity();
    for (const Slot* slot : active_) next = std::min(next, slot->effect->next_event_time());
    return next;
}

bool System::quasi_static_regime(const StageView& s) const {
    for (const Slot* slot : active_)
        if (!slot->effect->quasi_static_regime(s)) return false;
    return true;
}

void System::assemble_stiffness(const StageView& s, Eigen::SparseMatrix<double>& stiffness) {
    triplets_.clear();
    for (const Slot* slot : active_) slot->effect->add_stiffness(s, triplets_);
    stiffness.resize(layout_.dof(), layout_.dof());
    stiffness.setFromTriplets(triplets_.begin(), triplets_.end());
}

double System::foreseen_event_time(const StageView& s) const {
    double next = std::numeric_limits<double>::infinity();
    for (const Slot* slot : active_) next = std::min(next, slot->effect->foreseen_event_time(s));
    return next;
}

void System::add_straight_path_work(double t1, const Eigen::VectorXd& y1) {
    if (!work_accounting()) return;
    const double h = t1 - t_;
    if (!(h > 0)) return;
    const StateLayout& l = layout_;
    path_state_ = y_;
    l.velocities(path_state_) = (l.positions(y1) - l.positions(y_)) / h;
    for (const std::size_t k : active_parts_) add_work(k, view_of(path_state_, layout_, t_), h / 2);
    l.positions(path_state_) = l.positions(y1);
    l.aux_variables(path_state_) = l.aux_variables(y1);
    for (const std::size_t k : active_parts_) add_work(k, view_of(path_state_, layout_, t1), h / 2);
}

void System::activate(const StageInfo* stage) {
    shown_ = false;
    stage_end_ = stage ? stage->t_start + stage->duration : std::numeric_limits<double>::infinity();
    active_.clear();
    active_parts_.clear();
    for (const Slot& slot : slots_) {
        const bool active =
            !stage || slot.active_in.empty() ||
            std::find(slot.active_in.begin(), slot.active_in.end(), stage->name) != slot.active_in.end();
        if (!active) continue;
        active_.push_back(&slot);
        for (std::size_t k = slot.first_part; k < slot.first_part + slot.part_count; ++k) active_parts_.push_back(k);
    }
}

void System::begin_stage(const StageInfo& stage) {
    activate(&stage);
    const StageView s = state();
    for (const Slot* slot : active_) slot->effect->begin_stage(stage, s);
}

void System::save_state(StateOut& out) const {
    out(t_, steps_, evaluations_, y_, work_, pending_work_, path_);
    for (const Slot& slot : slots_) slot.effect->save_state(out);
}

void System::restore_state(StateIn& in) {
    Eigen::VectorXd y;
    std::vector<double> work, pending;
    in(t_, steps_, evaluations_, y, work, pending, path_);
    shown_ = false;
    if (y.size() != y_.size() || work.size() != work_.size() || pending.size() != pending_work_.size())
        throw cereal::Exception("the checkpoint's state vector or work accounting does not fit this scene");
    y_ = std::move(y), work_ = std::move(work), pending_work_ = std::move(pending);
    for (Slot& slot : slots_) slot.effect->restore_state(in);
}

std::vector<std::string> System::not_checkpointable() const {
    std::vector<std::string> names;
    for (const Slot& slot : slots_)
        if (!slot.effect->checkpointable()) names.push_back(slot.effect->describe());
    return names;
}

void System::refresh() {
    if (shown_) return;
    evaluate_shown(t_, y_);
    shown_ = true;
}

void System::evaluate_shown(double t, const Eigen::VectorXd& y) {
    derivative(*this, t, y, scratch_, Evaluation::outside_step());
    const ForceView accelerations = forces_of(scratch_, layout_);
    for (int axis = 0; axis < layout_.dimension; ++axis)
        net_force_.col(axis) = accelerations.force.col(axis) * body_.mass;
}

std::vector<std::string> System::pipeline() const {
    std::vector<std::string> names;
    for (const std::size_t k : active_parts_) names.push_back(parts_[k]->describe());
    return names;
}

void derivative(System& system, double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy, const Evaluation& how) {
    const StateLayout& layout = system.layout();
    const Index n = layout.nodes, dof = layout.dof();
    dy.resize(y.size());
    // dy = [velocities | 0 ...] chunk by chunk: the velocities are y's entries one dof further on.
    for_each_chunk(dof, [&](Index from, Index to) {
        dy.segment(from, to - from) = y.segment(dof + from, to - from);
        dy.segment(dof + from, to - from).setZero();
    });
    layout.aux_variables(dy).setZero();
    system.add_forces(t, y, layout.after_positions(dy), how);
    ForceView f = forces_of(dy, layout);
    for_each_chunk(n, [&](Index from, Index to) {
        for (int axis = 0; axis < layout.dimension; ++axis)
            scale(&f.force(from, axis), system.inverse_mass().data() + from, to - from);
    });
}

}  // namespace frictionlab
