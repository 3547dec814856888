#pragma once
#include <limits>

namespace frictionlab {

/// The PI step-size controller of Hairer & Wanner's DOPRI5 code (Hairer, Norsett & Wanner, Solving
/// ODEs I, 2nd ed., §II.4, and Gustafsson 1991, doi:10.1145/108556.108575). With err_n the error
/// norm of step n (accepted when <= 1) and q = 5 (the order of the error estimate plus one),
///
///     h_{n+1} = h_n * clamp(safety * err_n^-(1/q - 0.75 beta) * err_{n-1}^beta, shrink_limit, growth_limit)
///
/// beta = 0.04 (Hairer's choice) damps the oscillation of the plain I controller (beta = 0) on steps limited by
/// stability rather than accuracy, which is where a stiff lattice spends most of its time. After a
/// rejection only the I part is used and the next accepted step may not grow (the error model has
/// just failed at that step).
class StepSizeController {
public:
    struct Params {
        double safety, growth_limit, shrink_limit;  // 0.9, 10, 0.2 in Hairer's code
    };
    explicit StepSizeController(const Params& p) : p_(p) {}

    /// The next step after step h was accepted with error norm err <= 1. `cap`: when h was cut short
    /// of the step the controller had proposed (to land on an event or within max_dt), that proposal:
    /// it is kept if the error, scaled to it as err ~ h^5, would still pass (a short step is no
    /// reason to grow from less), and the step follows the error as usual otherwise.
    double accepted(double err, double h, double cap = 0);
    /// The retry after step h was rejected with error norm err > 1 (or not finite): always shorter.
    double rejected(double err, double h);

    template <class Archive>
    void serialize(Archive& ar) {
        ar(previous_err_, after_rejection_);
    }

private:
    double exponent() const;  // of err in the I part
    double factor(double err) const;

    Params p_;
    double previous_err_ = 1e-4;  // Hairer's initial value: no memory yet
    bool after_rejection_ = false;
};

}  // namespace frictionlab
