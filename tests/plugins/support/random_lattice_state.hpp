#pragma once
// Bulk models with every node displaced at random from its reference position: states on which a
// test compares an effect's forces with its energy or its stiffness.
#include <random>
#include <string>

#include "bulk_at_rest.hpp"
#include "spring_lattice_2d.hpp"

namespace frictionlab::test_support {

/// A bulk model with every node displaced by up to u at random.
template <class Bulk>
struct RandomState : BulkAtRest<Bulk> {
    RandomState(const typename Bulk::Params& p, double u, unsigned seed) : BulkAtRest<Bulk>(p) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> d(-u, u);
        for (double& q : this->layout.positions(this->y)) q += d(rng);
    }
};

/// A small lattice (5 x 3, 1 mm spacing) displaced at random.
struct RandomLatticeState : RandomState<SpringLattice2d> {
    explicit RandomLatticeState(double u, const std::string& springs = "geometric", unsigned seed = 11)
        : RandomState(params(springs), u, seed) {}
    static SpringLattice2d::Params params(const std::string& springs) {
        SpringLattice2d::Params p = SpringLattice2d::spec().build({{"springs", springs}});
        p.nx = 5;
        p.nz = 3;
        p.length = 4e-3;
        p.height = 2e-3;
        return p;
    }
};

}  // namespace frictionlab::test_support
