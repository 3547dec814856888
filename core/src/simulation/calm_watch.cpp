#include "calm_watch.hpp"

#include <cmath>

#include <fmt/format.h>

namespace frictionlab {

double top_speed(const StageView& s, Index* node) {
    Index worst = 0;
    const double speed = s.velocity.square().rowwise().sum().sqrt().maxCoeff(&worst);
    if (node) *node = worst;
    return speed;
}

std::string CalmWatch::advice(double t_end, double speed, double limit) const {
    if (!taken_ || !(t_end > t_) || !(speed_ > 0) || !(speed > 0)) return {};
    const double rate = std::log(speed_ / speed) / (t_end - t_);  // 1/s: the top speed ~ exp(-rate t)
    if (!(rate > 0))
        return fmt::format(
            "its top speed did not fall from t = {:.6g} s ({:.3g} m/s) on: damp more, or look for "
            "what keeps it moving; a longer stage would not help",
            t_, speed_);
    const double more = std::log(speed / limit) / rate;
    return fmt::format(
        "its top speed fell from {:.3g} m/s at t = {:.6g} s, by a factor of e every {:.3g} s: "
        "at that rate it needs about {:.2g} s more, so settle for longer (with a margin: the rate "
        "is measured, not guaranteed) or damp more",
        speed_, t_, 1 / rate, more);
}

}  // namespace frictionlab
