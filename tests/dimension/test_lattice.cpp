#include "test_lattice.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"

namespace frictionlab::testing {

namespace {

using Bonds = std::vector<std::array<Index, 2>>;

/// Geometric central springs of rest length a on the bonds, in any dimension.
class Springs final : public Effect {
public:
    Springs(const Bonds& bonds, double k, double a) : bonds_(bonds), k_(k), a_(a) {}
    bool checkpointable() const override { return true; }
    std::string describe() const override { return fmt::format("test springs k={:g} N/m", k_); }
    std::string key() const override { return "test_springs"; }

    void add_forces(const StageView& s, ForceView& f) override {
        for (const auto& [i, j] : bonds_) {
            const Eigen::VectorXd d = (s.position.row(j) - s.position.row(i)).matrix().transpose();
            const Eigen::VectorXd force = k_ * (1 - a_ / d.norm()) * d;
            f.force.row(i) += force.transpose().array();
            f.force.row(j) -= force.transpose().array();
        }
    }
    double potential_energy(const StageView& s) const override {
        double energy = 0;
        for (const auto& [i, j] : bonds_) {
            const double stretch = (s.position.row(j) - s.position.row(i)).matrix().norm() - a_;
            energy += 0.5 * k_ * stretch * stretch;
        }
        return energy;
    }
    bool quasi_static_regime(const StageView&) const override { return true; }
    /// K = -dF/dq: G = k [(1 - a/r) I + (a/r^3) d d^T] on both nodes' diagonal blocks, -G off them.
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const override {
        const int dim = s.dimension();
        for (const auto& [i, j] : bonds_) {
            const Eigen::VectorXd d = (s.position.row(j) - s.position.row(i)).matrix().transpose();
            const double r = d.norm();
            const Eigen::MatrixXd g =
                k_ * (1 - a_ / r) * Eigen::MatrixXd::Identity(dim, dim) + k_ * a_ / (r * r * r) * d * d.transpose();
            for (int u = 0; u < dim; ++u)
                for (int w = 0; w < dim; ++w) {
                    const Index iu = s.position_index(i, u), iw = s.position_index(i, w);
                    const Index ju = s.position_index(j, u), jw = s.position_index(j, w);
                    stiffness.emplace_back(iu, iw, g(u, w));
                    stiffness.emplace_back(ju, jw, g(u, w));
                    stiffness.emplace_back(iu, jw, -g(u, w));
                    stiffness.emplace_back(ju, iw, -g(u, w));
                }
        }
    }

private:
    const Bonds& bonds_;
    double k_, a_;
};

/// -k0 (x - x0) - c0 v on every node along every axis.
class GroundSprings final : public Effect {
public:
    GroundSprings(const Body& body, double k0, double c0) : body_(body), k0_(k0), c0_(c0) {}
    bool checkpointable() const override { return true; }
    std::string describe() const override {
        return fmt::format("test ground springs k0={:g} N/m, c0={:g} N s/m", k0_, c0_);
    }
    std::string key() const override { return "test_ground_springs"; }
    void add_forces(const StageView& s, ForceView& f) override {
        f.force -= k0_ * (s.position - body_.reference_position) + c0_ * s.velocity;
    }
    double potential_energy(const StageView& s) const override {
        return 0.5 * k0_ * (s.position - body_.reference_position).square().sum();
    }
    bool quasi_static_regime(const StageView&) const override { return true; }
    void add_stiffness(const StageView& s, std::vector<Eigen::Triplet<double>>& stiffness) const override {
        for (Index i = 0; i < s.position.rows(); ++i)
            for (int a = 0; a < s.dimension(); ++a)
                stiffness.emplace_back(s.position_index(i, a), s.position_index(i, a), k0_);
    }

private:
    const Body& body_;
    double k0_, c0_;
};

/// c (v_j - v_i) on node i of every bond: linear in the velocities, no stiffness.
class Dashpots final : public Effect {
public:
    Dashpots(const Bonds& bonds, double c) : bonds_(bonds), c_(c) {}
    bool checkpointable() const override { return true; }
    std::string describe() const override { return fmt::format("test dashpots c={:g} N s/m", c_); }
    std::string key() const override { return "test_dashpots"; }
    void add_forces(const StageView& s, ForceView& f) override {
        for (const auto& [i, j] : bonds_) {
            const Eigen::ArrayXd force = c_ * (s.velocity.row(j) - s.velocity.row(i)).transpose();
            f.force.row(i) += force.transpose();
            f.force.row(j) -= force.transpose();
        }
    }
    bool quasi_static_regime(const StageView&) const override { return true; }

private:
    const Bonds& bonds_;
    double c_;
};

std::string dimension_rule(const TestLattice::Params& p) {
    if (p.dimension == 2 && p.ny != 1) return "a 2D lattice has one layer: ny must be 1";
    return {};
}

}  // namespace

ParamSpec<TestLattice::Params> TestLattice::spec() {
    ParamSpec<Params> s(
        "Point masses on a square (2D) or cubic (3D) lattice with geometric springs between nearest "
        "neighbours, optional ground springs and bond dashpots; for tests.");
    s.add("dimension", &Params::dimension, "Spatial dimension of the body.").at_least(2).at_most(3);
    s.add("nx", &Params::nx, "Nodes along x.").at_least(2);
    s.add("ny", &Params::ny, "Nodes along y (3D).").at_least(1);
    s.add("nz", &Params::nz, "Nodes along z.").at_least(2);
    s.add("spacing", &Params::spacing, "Rest length a of a spring.").unit("m").greater_than(0);
    s.add("mass", &Params::mass, "Mass of every node.").unit("kg").greater_than(0);
    s.add("stiffness", &Params::stiffness, "Stiffness k of a spring.").unit("N/m").greater_than(0);
    s.add("ground_stiffness", &Params::ground_stiffness, "Stiffness k0 of a node's ground spring, per axis.")
        .unit("N/m")
        .at_least(0);
    s.add("ground_damping", &Params::ground_damping, "Coefficient c0 of a node's ground dashpot, per axis.")
        .unit("N s/m")
        .at_least(0);
    s.add("damping", &Params::damping, "Coefficient c of a bond's dashpot.").unit("N s/m").at_least(0);
    s.rule("ny", dimension_rule);
    s.dimensions({2, 3});
    s.body_dimension([](const Params& p) { return p.dimension; });
    return s;
}

TestLattice::TestLattice(const Params& p, const Context&) : p_(spec().checked(p)) {
    const int dim = p_.dimension;
    const Index n = p_.nx * ny() * p_.nz;
    const double a = p_.spacing;
    body_.reference_position.resize(n, dim);
    for (Index iz = 0; iz < p_.nz; ++iz)
        for (Index iy = 0; iy < ny(); ++iy)
            for (Index ix = 0; ix < p_.nx; ++ix) {
                const Index i = node(ix, iy, iz);
                body_.reference_position(i, 0) = ix * a;
                if (dim == 3) body_.reference_position(i, 1) = iy * a;
                body_.reference_position(i, dim - 1) = iz * a;
                body_.node_sets["all"].push_back(i);
                if (iz == 0) body_.node_sets["interface"].push_back(i);
                if (iz == p_.nz - 1) body_.node_sets["top"].push_back(i);
                if (ix == 0) body_.node_sets["trailing_edge"].push_back(i);
                if (ix == p_.nx - 1) body_.node_sets["leading_edge"].push_back(i);
                if (ix + 1 < p_.nx) bonds_.push_back({i, node(ix + 1, iy, iz)});
                if (iy + 1 < ny()) bonds_.push_back({i, node(ix, iy + 1, iz)});
                if (iz + 1 < p_.nz) bonds_.push_back({i, node(ix, iy, iz + 1)});
            }
    body_.mass = Eigen::ArrayXd::Constant(n, p_.mass);
    body_.length = (p_.nx - 1) * a;
    body_.height = (p_.nz - 1) * a;
    body_.width = ny() > 1 ? (ny() - 1) * a : a;
    body_.spacing = a;
    body_.bond_stiffness = p_.stiffness;
    body_.wave_speed = a * std::sqrt(p_.stiffness / p_.mass);  // a chain's long-wave speed
    body_.contact_frame = ContactFrame::horizontal_base(dim);
    body_.bonds = bonds_;
}

std::vector<std::unique_ptr<Effect>> TestLattice::effects(const Context&) {
    std::vector<std::unique_ptr<Effect>> out;
    out.push_back(std::make_unique<Springs>(bonds_, p_.stiffness, p_.spacing));
    if (p_.ground_stiffness > 0 || p_.ground_damping > 0)
        out.push_back(std::make_unique<GroundSprings>(body_, p_.ground_stiffness, p_.ground_damping));
    if (p_.damping > 0) out.push_back(std::make_unique<Dashpots>(bonds_, p_.damping));
    return out;
}

Index TestLattice::chain_length(int axis) const {
    if (axis == 0) return p_.nx;
    return axis == p_.dimension - 1 ? p_.nz : ny();
}

double TestLattice::mode_frequency(int axis, int j) const {
    const double s = std::sin(j * std::numbers::pi / (2.0 * static_cast<double>(chain_length(axis))));
    return std::sqrt((p_.ground_stiffness + 4 * p_.stiffness * s * s) / p_.mass);
}

Index TestLattice::position_along(Index i, int axis) const {
    if (axis == 0) return i % p_.nx;
    if (axis == p_.dimension - 1) return i / (p_.nx * ny());
    return (i / p_.nx) % ny();
}

double TestLattice::mode_shape(int axis, int j, Index i) const {
    return std::cos(j * std::numbers::pi * (static_cast<double>(position_along(i, axis)) + 0.5) /
                    static_cast<double>(chain_length(axis)));
}

}  // namespace frictionlab::testing
