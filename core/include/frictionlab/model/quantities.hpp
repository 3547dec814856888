#pragma once
// Named quantities that effects publish and observers read, so an observer written out of tree can
// show anything a friction law or loader computes without either knowing the other.
//
// A field is an array over a node set (e.g. "normal_force" over "interface"); a scalar is one number
// (e.g. "driving_force"). Storage is owned here and never moves, so an effect keeps a reference to
// its array and writes it in place, at every force evaluation. Values an observer sees are those of
// the last evaluation, which the run refreshes at the accepted state before observing.
#include <map>
#include <string>
#include <string_view>

#include <Eigen/Core>

namespace frictionlab {

class Quantities {
public:
    struct Field {
        std::string node_set, unit, doc;
        Eigen::ArrayXd values;
    };
    struct Scalar {
        std::string unit, doc;
        double value = 0;
    };

    /// Declares (or, if already declared with the same node set and size, returns) a field.
    Eigen::ArrayXd& field(const std::string& name, const std::string& node_set, Eigen::Index size,
                          std::string unit, std::string doc);
    double& scalar(const std::string& name, std::string unit, std::string doc);

    const Field* find_field(std::string_view name) const;
    const Scalar* find_scalar(std::string_view name) const;
    const std::map<std::string, Field, std::less<>>& fields() const { return fields_; }
    const std::map<std::string, Scalar, std::less<>>& scalars() const { return scalars_; }

private:
    std::map<std::string, Field, std::less<>> fields_;
    std::map<std::string, Scalar, std::less<>> scalars_;
};

}  // namespace frictionlab
