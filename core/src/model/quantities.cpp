#include "frictionlab/model/quantities.hpp"

#include "frictionlab/base/errors.hpp"

namespace frictionlab {

Eigen::ArrayXd& Quantities::field(const std::string& name, const std::string& node_set, Eigen::Index size,
                                  std::string unit, std::string doc) {
    auto [it, inserted] = fields_.try_emplace(name);
    Field& f = it->second;
    if (inserted) {
        f = Field{node_set, std::move(unit), std::move(doc), Eigen::ArrayXd::Zero(size)};
    } else if (f.node_set != node_set || f.values.size() != size) {
        throw InputError("quantity '" + name + "' is declared twice with different node sets ('" + f.node_set +
                         "' and '" + node_set + "')");
    }
    return f.values;
}

double& Quantities::scalar(const std::string& name, std::string unit, std::string doc) {
    auto [it, inserted] = scalars_.try_emplace(name);
    if (inserted) it->second = Scalar{std::move(unit), std::move(doc), 0.0};
    return it->second.value;
}

const Quantities::Field* Quantities::find_field(std::string_view name) const {
    auto it = fields_.find(name);
    return it == fields_.end() ? nullptr : &it->second;
}

const Quantities::Scalar* Quantities::find_scalar(std::string_view name) const {
    auto it = scalars_.find(name);
    return it == scalars_.end() ? nullptr : &it->second;
}

}  // namespace frictionlab
