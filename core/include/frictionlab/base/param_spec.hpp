#pragma once
// Parameters of a plugin type, declared once beside the type.
//
// A type binds scene keys to members of its typed `Params` struct:
//
//     static ParamSpec<Params> spec() {
//         ParamSpec<Params> s("Three-state junction friction (Li et al. 2020).");
//         s.add("mu_s", &Params::mu_s, "Static coefficient of one micro-contact.").greater_than(0);
//         return s;
//     }
//
// Defaults are the member initialisers of `Params`. The same declaration drives scene validation,
// `frictionlab doc` and `frictionlab example`; constructors only ever see a filled `Params`. An
// enumeration is bound once, names to values, and the member holds the value:
//
//     s.choice("removal", &Params::removal, {{"random", Removal::random}, {"oldest", Removal::oldest}},
//              "Which junctions go when P_b falls.");
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "frictionlab/base/errors.hpp"

namespace frictionlab {

enum class ValueType { boolean, integer, real, string, real_list, string_list };

using ParamValue = std::variant<bool, std::int64_t, double, std::string, std::vector<double>, std::vector<std::string>>;

/// The values of one component, key -> value, as read from a scene (defaults filled in).
using ParamValues = std::map<std::string, ParamValue, std::less<>>;

/// Everything a user needs to know about one key: the single source for docs and validation.
struct ParamInfo {
    std::string key;
    std::string doc;
    std::string unit;  // SI unit, "1" for dimensionless, empty where meaningless (names, flags)
    ValueType type = ValueType::real;
    ParamValue default_value;
    bool required = false;
    std::optional<double> greater_than, at_least, less_than, at_most;  // numeric bounds
    /// An integer member narrower than the scene's 64 bits: the values it can hold. A value outside
    /// would wrap around when stored (nx = 4294967307 would build 11 columns).
    std::optional<std::pair<std::int64_t, std::int64_t>> integer_range;
    std::vector<std::string> choices;  // allowed strings
    bool names_stage = false;          // a string that must name a stage of the scene ("" names none)
    /// A time that must not exceed the stage the key of this name names (its shortest stage of that
    /// name; "" names none: the whole run), e.g. how long an observer waits within the stage it observes.
    std::string within_stage_of;
    std::vector<std::string> also_known_as;  // other names for it (a former name, another symbol): did-you-mean only
    /// A number that may also be `auto`, stored as NaN: the component derives it from the scene and
    /// reports what it chose (Context::resolved), as `check` prints it.
    bool may_be_auto = false;
};

/// A file or folder a component writes at the top of the run's output directory, and the key whose
/// value names it ("" for a fixed name).
struct OutputName {
    std::string key;
    std::string name;
};
/// A type's outputs for given values (ParamSpec::writes), type-erased for the registry.
using OutputNames = std::function<std::vector<OutputName>(const ParamValues&)>;

/// A rule between several keys, checked after every key is individually valid.
struct ParamRule {
    std::string key;                                       // the key an error is reported at
    std::function<std::string(const ParamValues&)> check;  // empty string = fine
};

std::string to_string(ValueType);
std::string to_string(const ParamValue&);
/// The bound or choice `value` violates, or "" if it satisfies every constraint of `info`.
std::string violated_constraint(const ParamInfo& info, const ParamValue& value);

namespace detail {
template <class T>
struct value_type_of;
template <>
struct value_type_of<bool> {
    static constexpr auto type = ValueType::boolean;
    using stored = bool;
};
template <>
struct value_type_of<int> {
    static constexpr auto type = ValueType::integer;
    using stored = std::int64_t;
};
template <>
struct value_type_of<std::int64_t> {
    static constexpr auto type = ValueType::integer;
    using stored = std::int64_t;
};
template <>
struct value_type_of<double> {
    static constexpr auto type = ValueType::real;
    using stored = double;
};
template <>
struct value_type_of<std::string> {
    static constexpr auto type = ValueType::string;
    using stored = std::string;
};
template <>
struct value_type_of<std::vector<double>> {
    static constexpr auto type = ValueType::real_list;
    using stored = std::vector<double>;
};
template <>
struct value_type_of<std::vector<std::string>> {
    static constexpr auto type = ValueType::string_list;
    using stored = std::vector<std::string>;
};
}  // namespace detail

template <class P>
class ParamSpec {
public:
    /// Fluent access to one declared key; returned by add().
    class Field {
    public:
        Field(ParamSpec& spec, std::size_t index) : spec_(&spec), index_(index) {}
        Field& unit(std::string u) {
            info().unit = std::move(u);
            return *this;
        }
        Field& greater_than(double v) {
            info().greater_than = v;
            return *this;
        }
        Field& at_least(double v) {
            info().at_least = v;
            return *this;
        }
        Field& less_than(double v) {
            info().less_than = v;
            return *this;
        }
        Field& at_most(double v) {
            info().at_most = v;
            return *this;
        }
        /// The names each item of a string list may take (a single enumerated value is choice()).
        Field& items_one_of(std::vector<std::string> c) {
            info().choices = std::move(c);
            return *this;
        }
        /// The value names a stage of the scene (or is empty); the scene check refuses any other.
        Field& names_a_stage() {
            info().names_stage = true;
            return *this;
        }
        /// A time no longer than the stage that key `stage_key` names (the whole run while it names none).
        Field& within_stage(std::string stage_key) {
            info().within_stage_of = std::move(stage_key);
            return *this;
        }
        /// Another name the quantity is known by: a name the key had before, or the symbol other
        /// texts use for it (mu_k for the kinetic coefficient mu_d). Only the did-you-mean reads it:
        /// an unknown key is otherwise answered with the closest name by spelling, which may be a
        /// sibling of another meaning (mu_k is as close to mu_s as to mu_d); a scene that uses this
        /// name is told the key. It is not accepted in place of the key.
        Field& also_known_as(std::string name) {
            info().also_known_as.push_back(std::move(name));
            return *this;
        }
        /// A number that may be written `auto` (stored as NaN, the member's default when it is NaN):
        /// the component derives the value from the scene and records its choice.
        Field& or_auto() {
            info().may_be_auto = true;
            return *this;
        }
        /// The key must be given in the scene; the member initialiser is then only an example value.
        Field& required() {
            info().required = true;
            return *this;
        }

    private:
        ParamInfo& info() { return spec_->infos_[index_]; }
        ParamSpec* spec_;
        std::size_t index_;
    };

    explicit ParamSpec(std::string summary = {}) : summary_(std::move(summary)) {}

    template <class T>
    Field add(std::string key, T P::*member, std::string doc) {
        using traits = detail::value_type_of<T>;
        using stored = typename traits::stored;
        ParamInfo info;
        info.key = std::move(key);
        info.doc = std::move(doc);
        info.type = traits::type;
        info.default_value = stored(P{}.*member);
        if constexpr (traits::type == ValueType::integer && !std::is_same_v<T, stored>)
            info.integer_range = {std::numeric_limits<T>::min(), std::numeric_limits<T>::max()};
        infos_.push_back(std::move(info));
        setters_.push_back([member](P& p, const ParamValue& v) { p.*member = static_cast<T>(std::get<stored>(v)); });
        getters_.push_back([member](const P& p) -> ParamValue { return stored(p.*member); });
        return Field(*this, infos_.size() - 1);
    }

    /// A key whose value is one of `options`' names, stored as the matching value of the enumeration
    /// E; the default is the name of the member initialiser's value.
    template <class E>
    Field choice(std::string key, E P::*member, std::vector<std::pair<std::string, E>> options, std::string doc) {
        static_assert(std::is_enum_v<E>, "choice() binds an enumeration; use add() for other types");
        ParamInfo info;
        info.key = std::move(key);
        info.doc = std::move(doc);
        info.type = ValueType::string;
        for (const auto& [name, value] : options) {
            info.choices.push_back(name);
            if (value == P{}.*member) info.default_value = name;
        }
        if (!std::holds_alternative<std::string>(info.default_value))
            throw std::logic_error("ParamSpec::choice: the default of '" + info.key + "' is none of its options");
        infos_.push_back(std::move(info));
        getters_.push_back([member, options](const P& p) -> ParamValue {
            for (const auto& [name, value] : options)
                if (value == p.*member) return name;
            return std::string("(not a named value)");
        });
        setters_.push_back([member, options = std::move(options)](P& p, const ParamValue& v) {
            for (const auto& [name, value] : options)
                if (name == std::get<std::string>(v)) p.*member = value;
        });
        return Field(*this, infos_.size() - 1);
    }

    /// A constraint across keys, e.g. mu_d * tan(phi0) < 1. `check` sees the filled Params and
    /// returns an error message, or "" when the values are consistent.
    ParamSpec& rule(std::string key, std::function<std::string(const P&)> check) {
        rules_.push_back({std::move(key), std::move(check)});
        return *this;
    }

    /// Declares the files and folders the type writes in the run's output directory, from its
    /// Params, so that the scene check refuses two outputs of one run with the same name.
    ParamSpec& writes(std::function<std::vector<OutputName>(const P&)> outputs) {
        outputs_ = std::move(outputs);
        return *this;
    }

    /// Declares a loader that drives the slider (a moving spring or plate): loading starts with the
    /// first stage it acts in, the origin of every table's `time_since_loading` (loading_start()).
    ParamSpec& drives_loading() {
        drives_loading_ = true;
        return *this;
    }
    bool drives() const { return drives_loading_; }

    /// The spatial dimensions of the bodies the type works on, 2 and/or 3 (Body::dimension()); with
    /// `limit`, why not in the others, in the language of the physics. A scene whose body has
    /// another dimension is refused by the scene check, at the type, with the limit. A type that
    /// declares nothing works in 2D only: it was written when every body was planar. A bulk model
    /// declares the dimensions of the bodies it builds; with several, body_dimension() says which
    /// one its parameters choose.
    ParamSpec& dimensions(std::vector<int> dims, std::string limit = {}) {
        dimensions_ = std::move(dims);
        dimension_limit_ = std::move(limit);
        return *this;
    }
    ParamSpec& body_dimension(std::function<int(const P&)> of) {
        body_dimension_ = std::move(of);
        return *this;
    }
    const std::vector<int>& spatial_dimensions() const { return dimensions_; }
    const std::string& dimension_limit() const { return dimension_limit_; }
    /// The dimension of the body a bulk model of these values builds, type-erased for the registry.
    std::function<int(const ParamValues&)> erased_body_dimension() const {
        if (!body_dimension_) return [d = dimensions_.front()](const ParamValues&) { return d; };
        return [this_copy = *this](const ParamValues& v) { return this_copy.body_dimension_(this_copy.build(v)); };
    }

    const std::string& summary() const { return summary_; }
    const std::vector<ParamInfo>& params() const { return infos_; }

    /// Params from validated values; keys that are absent keep their defaults.
    P build(const ParamValues& values) const {
        P p{};
        for (std::size_t i = 0; i < infos_.size(); ++i)
            if (auto it = values.find(infos_[i].key); it != values.end()) setters_[i](p, it->second);
        return p;
    }

    /// `p` itself when every key satisfies its bounds and choices and every rule holds, else an
    /// InputError naming the first key at fault. Constructors call it on their Params, so Params
    /// built in code pass the very checks a scene passes (violated_constraint and the rules).
    const P& checked(const P& p) const {
        for (std::size_t i = 0; i < infos_.size(); ++i) {
            const ParamValue value = getters_[i](p);
            if (std::string why = violated_constraint(infos_[i], value); !why.empty())
                throw InputError(infos_[i].key + " " + why);
        }
        for (const auto& r : rules_)
            if (std::string why = r.check(p); !why.empty()) throw InputError(r.key + ": " + why);
        return p;
    }

    /// The value of `key` in `p` as a scene writes it (a choice by its name), e.g. for describe().
    std::string text(const P& p, std::string_view key) const {
        for (std::size_t i = 0; i < infos_.size(); ++i)
            if (infos_[i].key == key) return to_string(getters_[i](p));
        throw std::logic_error("ParamSpec::text: no key '" + std::string(key) + "'");
    }

    /// The cross-key rules, type-erased for the registry.
    std::vector<ParamRule> erased_rules() const {
        std::vector<ParamRule> out;
        for (const auto& r : rules_)
            out.push_back({r.key, [this_copy = *this, check = r.check](const ParamValues& v) {
                               return check(this_copy.build(v));
                           }});
        return out;
    }

    /// The outputs writes() declared, type-erased for the registry; empty if none were.
    OutputNames erased_outputs() const {
        if (!outputs_) return {};
        return [this_copy = *this](const ParamValues& v) { return this_copy.outputs_(this_copy.build(v)); };
    }

private:
    struct TypedRule {
        std::string key;
        std::function<std::string(const P&)> check;
    };
    std::string summary_;
    std::vector<ParamInfo> infos_;
    std::vector<std::function<void(P&, const ParamValue&)>> setters_;
    std::vector<std::function<ParamValue(const P&)>> getters_;
    std::vector<TypedRule> rules_;
    std::function<std::vector<OutputName>(const P&)> outputs_;
    bool drives_loading_ = false;
    std::vector<int> dimensions_{2};
    std::string dimension_limit_;
    std::function<int(const P&)> body_dimension_;
};

}  // namespace frictionlab
