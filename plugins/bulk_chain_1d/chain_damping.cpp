#include "chain_damping.hpp"

#include <fmt/format.h>

namespace frictionlab {

ChainDamping::ChainDamping(Index nodes, double eta) : nodes_(nodes), eta_(eta) {}

std::string ChainDamping::describe() const { return fmt::format("chain damping eta={:.3g} N s/m", eta_); }

void ChainDamping::add_forces(const StageView& s, ForceView& f) {
    const Index bonds = nodes_ - 1;
    const auto drag = eta_ * (s.vx.tail(bonds) - s.vx.head(bonds));
    f.fx.head(bonds) += drag;
    f.fx.tail(bonds) -= drag;
}

}  // namespace frictionlab
