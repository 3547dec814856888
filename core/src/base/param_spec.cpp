#include "frictionlab/base/param_spec.hpp"

#include <cmath>

#include <fmt/format.h>

namespace frictionlab {

std::string to_string(ValueType type) {
    switch (type) {
        case ValueType::boolean:
            return "boolean";
        case ValueType::integer:
            return "integer";
        case ValueType::real:
            return "number";
        case ValueType::string:
            return "string";
        case ValueType::real_list:
            return "list of numbers";
        case ValueType::string_list:
            return "list of strings";
    }
    return "?";
}

namespace {
std::string join_list(const auto& items, auto&& fmt_one) {
    std::string out = "[";
    for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + fmt_one(items[i]);
    return out + "]";
}
}  // namespace

std::string to_string(const ParamValue& value) {
    struct Visitor {
        std::string operator()(bool b) const { return b ? "true" : "false"; }
        std::string operator()(std::int64_t i) const { return std::to_string(i); }
        // NaN is refused as a value unless the key may be auto, whose stored form it is.
        std::string operator()(double d) const { return std::isnan(d) ? "auto" : fmt::format("{:g}", d); }
        std::string operator()(const std::string& s) const { return s; }
        std::string operator()(const std::vector<double>& v) const {
            return join_list(v, [](double d) { return fmt::format("{:g}", d); });
        }
        std::string operator()(const std::vector<std::string>& v) const {
            return join_list(v, [](const std::string& s) { return s; });
        }
    };
    return std::visit(Visitor{}, value);
}

namespace {
std::string numeric_violation(const ParamInfo& p, double x) {
    if (!std::isfinite(x)) return fmt::format("must be a finite number, got {}", x);
    if (p.greater_than && !(x > *p.greater_than)) return fmt::format("must be > {:g}, got {:g}", *p.greater_than, x);
    if (p.at_least && !(x >= *p.at_least)) return fmt::format("must be >= {:g}, got {:g}", *p.at_least, x);
    if (p.less_than && !(x < *p.less_than)) return fmt::format("must be < {:g}, got {:g}", *p.less_than, x);
    if (p.at_most && !(x <= *p.at_most)) return fmt::format("must be <= {:g}, got {:g}", *p.at_most, x);
    return {};
}
std::string choice_violation(const ParamInfo& p, const std::string& s) {
    if (p.choices.empty()) return {};
    for (const auto& c : p.choices)
        if (c == s) return {};
    return "must be one of " + join_list(p.choices, [](const std::string& c) { return "'" + c + "'"; }) + ", got '" +
           s + "'";
}
}  // namespace

std::string violated_constraint(const ParamInfo& info, const ParamValue& value) {
    if (auto* d = std::get_if<double>(&value)) {
        if (!info.may_be_auto) return numeric_violation(info, *d);
        if (std::isnan(*d)) return "";  // auto: the component's to choose
        const auto m = numeric_violation(info, *d);
        return m.empty() ? m : m + ", or auto";
    }
    if (auto* i = std::get_if<std::int64_t>(&value)) {
        if (const auto& range = info.integer_range; range && (*i < range->first || *i > range->second))
            return fmt::format("must be between {} and {} (the range of its integer type), got {}", range->first,
                               range->second, *i);
        return numeric_violation(info, static_cast<double>(*i));
    }
    if (auto* v = std::get_if<std::vector<double>>(&value)) {
        for (std::size_t k = 0; k < v->size(); ++k)
            if (auto m = numeric_violation(info, (*v)[k]); !m.empty()) return fmt::format("item {}: {}", k, m);
        return {};
    }
    if (auto* s = std::get_if<std::string>(&value)) return choice_violation(info, *s);
    if (auto* l = std::get_if<std::vector<std::string>>(&value)) {
        for (std::size_t k = 0; k < l->size(); ++k)
            if (auto m = choice_violation(info, (*l)[k]); !m.empty()) return fmt::format("item {}: {}", k, m);
    }
    return {};
}

}  // namespace frictionlab
