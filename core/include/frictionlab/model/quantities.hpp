#pragma once
// Named quantities that effects publish and observers read, so an observer written out of tree can
// show anything a friction law or loader computes without either knowing the other.
//
// A field is an array over a node set (e.g. "normal_force" over "interface"); a scalar is one number
// (e.g. "driving_force"). Storage is owned here and never moves, so an effect keeps a reference to
// its array and writes it in place, at every force evaluation. Values an observer sees are those of
// the last evaluation, which the run refreshes at the accepted state before observing.
//
// An effect that computes a field publishes it (field()); a component that only reads another's
// field (a friction law reads the base contact's "normal_force" in its force evaluation, an observer
// the junction counts) declares it needed (needed_field()) when it is built, and a field needed but
// never published is a scene error at assembly (unpublished_fields()), rather than zeros in the force
// loop or a run that stops at its start. A reader may say what the user can change instead (an
// observer's option that does without the field), so the error names the fix.
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "frictionlab/model/component.hpp"

namespace frictionlab {

class Quantities {
public:
    /// A component that declared a field needed, and what to change in the scene if none publishes it.
    struct Reader {
        std::string component;  // its place in the scene, e.g. "observers[1]"
        std::string remedy;     // e.g. "set criterion: slip"; empty: add an effect that publishes it
        bool operator==(const Reader&) const = default;
    };
    struct Field {
        std::string node_set, unit, doc;
        Eigen::ArrayXd values;
        bool published = false;       // some effect computes it
        std::vector<Reader> readers;  // the components that declared it needed
    };
    struct Scalar {
        std::string unit, doc;
        double value = 0;
    };

    /// Publishes (or, if already declared with the same node set and size, returns) a field that
    /// the caller computes.
    Eigen::ArrayXd& field(const std::string& name, const std::string& node_set, Eigen::Index size, std::string unit,
                          std::string doc);
    /// A field `reader` (its place in the scene, e.g. "friction") reads and another effect must
    /// publish; the storage is the publisher's, whichever declares it first. `remedy`: what the
    /// reader's user can change instead, should no effect publish it.
    const Eigen::ArrayXd& needed_field(const std::string& name, const std::string& node_set, Eigen::Index size,
                                       std::string reader, std::string remedy = {});
    /// Fields declared needed that no effect published, one entry per field and reader, by field name.
    struct Unpublished {
        std::string name, node_set;
        Reader reader;
    };
    std::vector<Unpublished> unpublished_fields() const;
    double& scalar(const std::string& name, std::string unit, std::string doc);

    const Field* find_field(std::string_view name) const;
    const Scalar* find_scalar(std::string_view name) const;
    const std::map<std::string, Field, std::less<>>& fields() const { return fields_; }
    /// Checkpoints: every value as the last evaluation or commit left it (junction counts, say,
    /// change only at commits), by name.
    void save_state(StateOut& out) const;
    void restore_state(StateIn& in);
    const std::map<std::string, Scalar, std::less<>>& scalars() const { return scalars_; }

    /// Every field's and scalar's value, in name order: the quantities at one state (System keeps
    /// them at both ends of a straight path).
    struct Values {
        std::vector<Eigen::ArrayXd> fields;
        std::vector<double> scalars;
        template <class Archive>
        void serialize(Archive& ar) {
            ar(fields, scalars);
        }
    };
    void copy_to(Values& values) const;
    /// Every value to (1 - w) a + w b, a and b copied from this same set of quantities.
    void set_between(const Values& a, const Values& b, double w);

private:
    std::map<std::string, Field, std::less<>> fields_;
    std::map<std::string, Scalar, std::less<>> scalars_;
};

}  // namespace frictionlab
