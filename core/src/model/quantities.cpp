#include "frictionlab/model/quantities.hpp"

#include "frictionlab/base/state_archive.hpp"

#include "frictionlab/base/errors.hpp"

namespace frictionlab {

namespace {

Quantities::Field& declared(std::map<std::string, Quantities::Field, std::less<>>& fields, const std::string& name,
                            const std::string& node_set, Eigen::Index size) {
    auto [it, inserted] = fields.try_emplace(name);
    Quantities::Field& f = it->second;
    if (inserted) {
        f.node_set = node_set;
        f.values = Eigen::ArrayXd::Zero(size);
    } else if (f.node_set != node_set || f.values.size() != size) {
        throw InputError("quantity '" + name + "' is declared twice with different node sets ('" + f.node_set +
                         "' and '" + node_set + "')");
    }
    return f;
}

}  // namespace

Eigen::ArrayXd& Quantities::field(const std::string& name, const std::string& node_set, Eigen::Index size,
                                  std::string unit, std::string doc) {
    Field& f = declared(fields_, name, node_set, size);
    if (!f.published) f.unit = std::move(unit), f.doc = std::move(doc), f.published = true;
    return f.values;
}

const Eigen::ArrayXd& Quantities::needed_field(const std::string& name, const std::string& node_set, Eigen::Index size,
                                               std::string reader, std::string remedy) {
    Field& f = declared(fields_, name, node_set, size);
    f.readers.push_back({std::move(reader), std::move(remedy)});
    return f.values;
}

std::vector<Quantities::Unpublished> Quantities::unpublished_fields() const {
    std::vector<Unpublished> out;
    for (const auto& [name, f] : fields_)
        if (!f.published)
            for (const auto& reader : f.readers) out.push_back({name, f.node_set, reader});
    return out;
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

void Quantities::copy_to(Values& values) const {
    values.fields.resize(fields_.size());
    values.scalars.resize(scalars_.size());
    std::size_t k = 0;
    for (const auto& [name, f] : fields_) values.fields[k++] = f.values;
    k = 0;
    for (const auto& [name, s] : scalars_) values.scalars[k++] = s.value;
}

void Quantities::set_between(const Values& a, const Values& b, double w) {
    std::size_t k = 0;
    for (auto& [name, f] : fields_) {
        f.values = (1 - w) * a.fields[k] + w * b.fields[k];  // same size: the storage stays put
        ++k;
    }
    k = 0;
    for (auto& [name, s] : scalars_) {
        s.value = (1 - w) * a.scalars[k] + w * b.scalars[k];
        ++k;
    }
}

void Quantities::save_state(StateOut& out) const {
    out(static_cast<std::uint64_t>(fields_.size()));
    for (const auto& [name, f] : fields_) out(name, f.values);
    out(static_cast<std::uint64_t>(scalars_.size()));
    for (const auto& [name, s] : scalars_) out(name, s.value);
}

void Quantities::restore_state(StateIn& in) {
    const auto mismatch = [](const std::string& name) {
        return cereal::Exception("the checkpoint's quantity '" + name + "' is not one this run publishes");
    };
    std::uint64_t count = 0;
    in(count);
    if (count != fields_.size()) throw cereal::Exception("the checkpoint has another set of published fields");
    for (std::uint64_t k = 0; k < count; ++k) {
        std::string name;
        Eigen::ArrayXd values;
        in(name, values);
        const auto f = fields_.find(name);
        if (f == fields_.end() || f->second.values.size() != values.size()) throw mismatch(name);
        f->second.values = values;  // same size: the storage the effects hold stays put
    }
    in(count);
    if (count != scalars_.size()) throw cereal::Exception("the checkpoint has another set of published scalars");
    for (std::uint64_t k = 0; k < count; ++k) {
        std::string name;
        double value = 0;
        in(name, value);
        const auto s = scalars_.find(name);
        if (s == scalars_.end()) throw mismatch(name);
        s->second.value = value;
    }
}

}  // namespace frictionlab
