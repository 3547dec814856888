#include "chain_springs.hpp"

#include <fmt/format.h>

namespace frictionlab {

ChainSprings::ChainSprings(Index nodes, double spacing, double stiffness)
    : nodes_(nodes), spacing_(spacing), stiffness_(stiffness) {}

std::string ChainSprings::describe() const {
    return fmt::format("chain springs {} nodes, k={:.4g} N/m", nodes_, stiffness_);
}

void ChainSprings::add_forces(const StageView& s, ForceView& f) {
    const Index bonds = nodes_ - 1;
    // Tension of bond i (between nodes i and i+1): + on node i, - on node i+1.
    const auto tension = stiffness_ * (s.x.tail(bonds) - s.x.head(bonds) - spacing_);
    f.fx.head(bonds) += tension;
    f.fx.tail(bonds) -= tension;
}

void ChainSprings::add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const {
    for (Index i = 0; i + 1 < nodes_; ++i) {
        const Index a = s.position_index(i, 0), b = s.position_index(i + 1, 0);  // x of the two blocks
        stiffness.emplace_back(a, a, stiffness_);
        stiffness.emplace_back(b, b, stiffness_);
        stiffness.emplace_back(a, b, -stiffness_);
        stiffness.emplace_back(b, a, -stiffness_);
    }
}

double ChainSprings::potential_energy(const StageView& s) const {
    const Index bonds = nodes_ - 1;
    return 0.5 * stiffness_ * (s.x.tail(bonds) - s.x.head(bonds) - spacing_).square().sum();
}

}  // namespace frictionlab
