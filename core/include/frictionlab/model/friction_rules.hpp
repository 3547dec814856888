#pragma once
// Parameter rules that several friction laws share, written once.
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace frictionlab {

/// "" when the coefficient of a moving contact (mu_d) does not exceed the static one; else
/// why it must not: the contact would carry more force moving than it takes to break it at rest.
inline std::string moving_not_above_static(std::string_view moving_key, double mu_moving, double mu_s) {
    if (mu_moving <= mu_s) return {};
    return fmt::format(
        "{} = {:.4g} exceeds mu_s = {:.4g}: a moving contact would carry more force than it takes "
        "to break it at rest",
        moving_key, mu_moving, mu_s);
}

}  // namespace frictionlab
