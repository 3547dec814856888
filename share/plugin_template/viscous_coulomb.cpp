// An out-of-tree FrictionLab plugin with one friction law: Coulomb friction smoothed near zero slip
// velocity, F_i = -mu f_N,i tanh(|v_i| / v_r) v_i / |v_i| on each interface block, v_i the block's
// velocity in the interface (its tangential axes: x on a 2D body, x and y on a 3D one; the body's
// contact frame says which axes they are). A friction law is an Effect:
// add_forces() is a pure function of the stage state (the integrator calls it several times per
// step); discrete transitions, if a law has any, go in commit(), once per accepted step.
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include <frictionlab/base/errors.hpp>
#include <frictionlab/model/kinds.hpp>
#include <frictionlab/base/param_spec.hpp>
#include <frictionlab/plugins/plugin.hpp>
#include <frictionlab/model/quantities.hpp>
#include <frictionlab/plugins/registry.hpp>

namespace {

using frictionlab::Index;

class ViscousCoulomb final : public frictionlab::FrictionLaw {
public:
    struct Params {
        double mu = 0.3;
        double regularisation_velocity = 1e-4;
        std::string node_set = "interface";
    };
    static constexpr std::string_view type = "viscous_coulomb";

    static frictionlab::ParamSpec<Params> spec() {
        frictionlab::ParamSpec<Params> s("Coulomb friction smoothed near rest: F = -mu f_N tanh(v / v_r) per block.");
        s.add("mu", &Params::mu, "Friction coefficient.").unit("1").greater_than(0);
        s.add("regularisation_velocity", &Params::regularisation_velocity,
              "Slip speed v_r over which the force reaches mu f_N (a dashpot mu f_N / v_r near rest).")
            .unit("m/s")
            .greater_than(0);
        s.add("node_set", &Params::node_set, "The bulk's node set in contact with the base.");
        s.dimensions({2, 3});  // it acts along the contact frame's tangential axes, one or two
        return s;
    }

    // spec().checked(): Params built in code pass the checks a scene's values pass.
    ViscousCoulomb(const Params& params, const frictionlab::Context& ctx) : p_(spec().checked(params)) {
        if (!ctx.body || !ctx.quantities)
            throw frictionlab::InputError("viscous_coulomb: needs the bulk model's body and the run's quantities");
        nodes_ = ctx.body->nodes(p_.node_set);
        tangential_ = ctx.body->contact_frame.tangential;
        const Index n = static_cast<Index>(nodes_.size());
        // The base contact (a loader, evaluated before the friction law) publishes the normal force
        // of each interface block; declaring it needed gives this law read access to it, and a scene
        // without a base contact is refused at this law rather than run with zeros.
        normal_force_ = &ctx.quantities->needed_field("normal_force", p_.node_set, n, ctx.name);
        friction_force_ = &ctx.quantities->field("friction_force", p_.node_set, n, "N", "x-force from friction.");
    }

    std::string describe() const override {
        return fmt::format("viscous Coulomb friction (mu={:g}, v_r={:g} m/s)", p_.mu, p_.regularisation_velocity);
    }

    void add_forces(const frictionlab::StageView& s, frictionlab::ForceView& f) override {
        for (std::size_t k = 0; k < nodes_.size(); ++k) {
            const Index node = nodes_[k];
            double speed = 0;  // |v| in the interface plane
            for (const int axis : tangential_) speed += s.velocity(node, axis) * s.velocity(node, axis);
            speed = std::sqrt(speed);
            if (!(speed > 0)) {
                (*friction_force_)(k) = 0;
                continue;
            }
            const double magnitude = p_.mu * (*normal_force_)(k)*std::tanh(speed / p_.regularisation_velocity);
            for (const int axis : tangential_) f.force(node, axis) -= magnitude * (s.velocity(node, axis) / speed);
            // published for observers: the force along the sliding direction (the frame's first axis)
            (*friction_force_)(k) = -magnitude * (s.velocity(node, tangential_.front()) / speed);
        }
    }

private:
    Params p_;
    frictionlab::NodeSet nodes_;
    std::vector<int> tangential_;  // the axes of the interface plane
    const Eigen::ArrayXd* normal_force_ = nullptr;
    Eigen::ArrayXd* friction_force_ = nullptr;
};

void register_types(frictionlab::Registry& registry) { registry.add<ViscousCoulomb>(); }

}  // namespace

FRICTIONLAB_PLUGIN("friction_viscous_coulomb", "0.1.0", register_types)
