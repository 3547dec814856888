#include "vertical_damping.hpp"

#include <fmt/format.h>

namespace frictionlab {

VerticalDamping::VerticalDamping(double eta) : eta_(eta) {}

std::string VerticalDamping::describe() const { return fmt::format("vertical damping eta_z={:.3g} N s/m", eta_); }

void VerticalDamping::add_forces(const StageView& s, ForceView& f) { f.fz -= eta_ * s.vz; }

}  // namespace frictionlab
