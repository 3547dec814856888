#pragma once
#include <optional>

#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/model/kinds.hpp"
#include "frictionlab/base/param_spec.hpp"

#include "error_norm.hpp"
#include "step_size_controller.hpp"

namespace frictionlab {

/// Dormand–Prince 5(4): the adaptive explicit Runge–Kutta pair of J. R. Dormand, P. J. Prince,
/// J. Comput. Appl. Math. 6 (1980) 19, doi:10.1016/0771-050X(80)90013-3, as in Hairer, Norsett &
/// Wanner, Solving ODEs I, §II.4-II.5. Seven stages k_1..k_7, the last at (t + h, y_{n+1}):
///
///     y_{n+1} = y_n + h sum_i b_i k_i       (5th order, advanced: local extrapolation)
///     e       = h sum_i (b_i - bhat_i) k_i  (the 4th-order solution's difference: the error estimate)
///
/// A step is accepted when ErrorNorm(e) <= 1; otherwise it is retried shorter within the same call
/// of step(), and the StepSizeController proposes the next step from the error.
///
/// Freeze and commit (theory.md B.17): every attempt starts with System::begin_step(), which resets
/// the step's pending work and lets effects record the step's start (idempotent: the shipped effects
/// only copy the accepted state); only the accepted attempt reaches System::accept(), so a rejected
/// attempt commits nothing. No FSAL: k_7 is evaluated with the discrete state frozen before the
/// commit, which may change it (a junction breaks), so it is not f at the next step's start; the
/// next step evaluates its own k_1 (7 evaluations per step, not 6).
///
/// Events: each step is at most min(h, max_dt, dt_max, next_event_time() - t), and a step cut to an
/// event is accepted at exactly the event time, so a friction law's scheduled transition (a junction
/// lifetime ending) is judged at the end of the step it falls in, at its own time.
///
/// Work accounting: the evaluations carry h b_i (b_2 = b_7 = 0), the 5th-order quadrature the state
/// is advanced with, so the energy balance closes to the step's accuracy.
///
/// Stability: the region reaches |h lambda| = 3.3 on the negative real axis, but the controller
/// keeps the step within it (a step beyond it fails the error test), so stability_radius() is
/// infinite and the run's pre-stage stable-step check does not refuse this integrator; its first
/// step is initial_step, capped by dt_max.
class DormandPrince final : public Integrator {
public:
    bool checkpointable() const override { return true; }
    void save_state(StateOut& out) const override { out(*this); }
    void restore_state(StateIn& in) override { in(*this); }
    template <class Archive>
    void serialize(Archive& ar) {
        ar(controller_, h_, accepted_, rejected_);
    }
    struct Params {
        double rtol = 1e-6;
        double atol_position = 1e-12;
        double atol_velocity = 1e-9;
        double atol_aux = 1e-9;
        double initial_step = 1e-7;
        double dt_max = 1e-5;
        double dt_min = 1e-15;
        double safety = 0.9;
        double growth_limit = 10;
        double shrink_limit = 0.2;
    };
    static constexpr std::string_view type = "dormand_prince";
    static ParamSpec<Params> spec();

    DormandPrince(const Params& p, const Context& ctx);
    ~DormandPrince() override;
    double step(System& system, double max_dt) override;
    double nominal_dt() const override { return p_.initial_step; }
    /// The propagated solution's order; its steps, and so the evaluations per step, vary.
    int order() const override { return 5; }

    /// Accepted and rejected attempts so far.
    long long accepted_steps() const { return accepted_; }
    long long rejected_steps() const { return rejected_; }
    /// The step the controller proposes next (before max_dt and events cut it).
    double proposed_step() const { return h_; }

private:
    /// One attempt of length h from the accepted state: fills y1_ and err_.
    void attempt(System& system, double h);
    [[noreturn]] void fail(const System& system, double h, const ErrorNorm::Result& worst) const;

    Params p_;
    spdlog::logger& log_;
    StepSizeController controller_;
    std::optional<ErrorNorm> norm_;  // built at the first step, when the layout is known
    double h_;
    long long accepted_ = 0, rejected_ = 0;
    Eigen::VectorXd k_[7], stage_, y1_, err_;
};

}  // namespace frictionlab
