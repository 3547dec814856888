#include "frictionlab/scene/values.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <regex>

#include <fmt/format.h>

namespace frictionlab::detail {

namespace {

// Plain scalars are typed by the YAML 1.2 core schema, narrowed: decimal integers only, no '_'
// separators, booleans true/false in the three spellings the schema allows. A quoted scalar is
// always a string.
bool is_null_text(const std::string& s) { return s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL"; }

std::optional<bool> parse_bool(const std::string& s) {
    if (s == "true" || s == "True" || s == "TRUE") return true;
    if (s == "false" || s == "False" || s == "FALSE") return false;
    return std::nullopt;
}

bool looks_like_integer(const std::string& s) {
    static const std::regex pattern("[-+]?[0-9]+");
    return std::regex_match(s, pattern);
}

std::string_view without_plus(const std::string& s) {
    std::string_view v = s;
    if (!v.empty() && v.front() == '+') v.remove_prefix(1);
    return v;
}

struct Number {
    std::optional<double> value;
    bool out_of_range = false;
};

Number parse_real(const std::string& s) {
    static const std::regex finite("[-+]?(\\.[0-9]+|[0-9]+(\\.[0-9]*)?)([eE][-+]?[0-9]+)?");
    static const std::regex infinite("[-+]?\\.(inf|Inf|INF)");
    static const std::regex nan("\\.(nan|NaN|NAN)");
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (std::regex_match(s, infinite)) return {s.front() == '-' ? -inf : inf};
    if (std::regex_match(s, nan)) return {std::numeric_limits<double>::quiet_NaN()};
    if (!std::regex_match(s, finite)) return {};
    const std::string_view v = without_plus(s);
    double x = 0;
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
    if (ec == std::errc::result_out_of_range) return {std::nullopt, true};
    if (ec != std::errc() || end != v.data() + v.size()) return {};
    return {x};
}

struct Integer {
    std::optional<std::int64_t> value;
    bool out_of_range = false;
};

Integer parse_integer(const std::string& s) {
    if (!looks_like_integer(s)) return {};
    const std::string_view v = without_plus(s);
    std::int64_t i = 0;
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), i);
    if (ec == std::errc::result_out_of_range) return {std::nullopt, true};
    return {i};
}

bool is_yaml11_bool(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s == "yes" || s == "no" || s == "on" || s == "off" || s == "y" || s == "n";
}

// What a user most likely meant when a scalar did not read as the expected type.
std::string hint(ValueType type, const YAML::Node& node) {
    const std::string& s = node.Scalar();
    const bool numeric = type == ValueType::integer || type == ValueType::real;
    if (is_quoted(node) && numeric && parse_real(s).value) return " (numbers are written without quotes)";
    if (is_quoted(node) && type == ValueType::boolean && parse_bool(s)) return " (booleans are written without quotes)";
    if (numeric && s.find('_') != std::string::npos) return " (write numbers without '_' separators)";
    if (type == ValueType::boolean && is_yaml11_bool(s)) return " (YAML 1.2 reads yes/no/on/off as strings)";
    return {};
}

struct Scalar {
    std::optional<ParamValue> value;
    std::string error;
};

Scalar type_error(const std::string& expected, ValueType type, const YAML::Node& node) {
    std::string message = "expected " + expected + ", got " + describe(node);
    if (node.IsScalar()) message += hint(type, node);
    return {std::nullopt, message};
}

// One scalar of the given type (a list's item type for lists).
Scalar read_scalar(ValueType type, const YAML::Node& node) {
    const bool plain = node.IsScalar() && !is_quoted(node);
    const std::string text = node.IsScalar() ? node.Scalar() : std::string();
    switch (type) {
        case ValueType::boolean:
            if (auto b = plain ? parse_bool(text) : std::nullopt) return {*b, {}};
            return type_error("true or false", type, node);
        case ValueType::integer: {
            const Integer i = plain ? parse_integer(text) : Integer{};
            if (i.value) return {*i.value, {}};
            if (i.out_of_range) return {std::nullopt, "integer out of range, got " + quote(text)};
            return type_error("an integer", type, node);
        }
        case ValueType::real: {
            const Number x = plain ? parse_real(text) : Number{};
            if (x.value) return {*x.value, {}};
            if (x.out_of_range) return {std::nullopt, "number out of the range of a double, got " + quote(text)};
            return type_error("a number", type, node);
        }
        default:
            if (node.IsScalar() && !(plain && is_null_text(text))) return {text, {}};
            return type_error("a string", type, node);
    }
}

ValueType item_type(ValueType list) { return list == ValueType::real_list ? ValueType::real : ValueType::string; }

bool report_if(const std::string& message, const YAML::Node& at, const std::string& path, const Reporter& reporter) {
    if (!message.empty()) reporter.error(at, path, message);
    return message.empty();
}

std::optional<ParamValue> read_scalar_value(const ParamInfo& info, const Entry& entry, const std::string& path,
                                            const Reporter& reporter) {
    const YAML::Node& node = entry.value;
    if (info.may_be_auto && node.IsScalar() && !is_quoted(node) && node.Scalar() == "auto")
        return ParamValue(std::numeric_limits<double>::quiet_NaN());
    Scalar s = read_scalar(info.type, entry.value);
    if (!s.value && info.may_be_auto && s.error.starts_with("expected a number"))
        s.error.insert(std::string_view("expected a number").size(), " or auto");
    if (s.value) s.error = violated_constraint(info, *s.value);
    if (!report_if(s.error, entry.site(), path, reporter)) return std::nullopt;
    return s.value;
}

template <class T>
std::optional<ParamValue> read_list(const ParamInfo& info, const Entry& entry, const std::string& path,
                                    const Reporter& reporter) {
    if (!entry.value.IsSequence()) {
        reporter.error(entry.site(), path, "expected " + expectation(info) + ", got " + describe(entry.value));
        return std::nullopt;
    }
    std::vector<T> items;
    bool valid = true;
    for (std::size_t k = 0; k < entry.value.size(); ++k) {
        const YAML::Node item = entry.value[k];
        Scalar s = read_scalar(item_type(info.type), item);
        if (s.value) s.error = violated_constraint(info, *s.value);
        valid = report_if(s.error, item, index_path(path, k), reporter) && valid;
        if (s.value) items.push_back(std::get<T>(*s.value));
    }
    if (!valid) return std::nullopt;
    return ParamValue(std::move(items));
}

void report_unknown(const YAML::Node& key, const std::string& path, const SectionKeys& keys, const Reporter& reporter) {
    std::vector<std::string> known;
    for (const auto& p : keys.params) known.push_back(p.key);
    known.insert(known.end(), keys.other_keys.begin(), keys.other_keys.end());
    const std::string name = key.Scalar();
    std::string guess;
    for (const auto& p : keys.params)
        if (std::find(p.also_known_as.begin(), p.also_known_as.end(), name) != p.also_known_as.end()) guess = p.key;
    if (guess.empty()) guess = did_you_mean(name, known);
    if (!guess.empty()) {
        reporter.error(key, join_path(path, name),
                       "unknown key " + quote(name) + "; did you mean " + quote(guess) + "?");
        return;
    }
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    reporter.error(key, join_path(path, name),
                   "unknown key " + quote(name) + " (the keys of " + keys.what + " are: " + list + ")");
}

bool is_whole(double x) { return std::isfinite(x) && x == std::trunc(x) && std::fabs(x) < 0x1p53; }

std::string real_text(double x) {
    if (std::isnan(x)) return "auto";  // the only NaN a scene holds: a key left to its component
    if (std::isinf(x)) return x > 0 ? ".inf" : "-.inf";
    char buffer[64];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
    std::string text(buffer, end);
    // Keep a real looking like one, so the resolved scene says what type each value has.
    if (text.find_first_of(".e") == std::string::npos) text += ".0";
    return text;
}

// A string that would read back as something else (or as nothing) is written in quotes.
bool needs_quotes(const std::string& s) {
    return is_null_text(s) || parse_bool(s) || parse_real(s).value || parse_real(s).out_of_range;
}

void emit_string(YAML::Emitter& out, const std::string& s) {
    if (needs_quotes(s)) out << YAML::DoubleQuoted;
    out << s;
}

}  // namespace

std::optional<ParamValue> read_value(const ParamInfo& info, const Entry& entry, const std::string& path,
                                     const Reporter& reporter) {
    switch (info.type) {
        case ValueType::real_list:
            return read_list<double>(info, entry, path, reporter);
        case ValueType::string_list:
            return read_list<std::string>(info, entry, path, reporter);
        default:
            return read_scalar_value(info, entry, path, reporter);
    }
}

std::string expectation(const ParamInfo& info) {
    const std::string unit = info.unit.empty() || info.unit == "1" ? "" : " in " + info.unit;
    const std::string choices = info.choices.empty() ? "" : ", each one of " + quote_list(info.choices);
    switch (info.type) {
        case ValueType::boolean:
            return "true or false";
        case ValueType::integer:
            return "an integer" + unit;
        case ValueType::real:
            return "a number" + unit + (info.may_be_auto ? " or auto" : "");
        case ValueType::string:
            return info.choices.empty() ? "a string" : "one of " + quote_list(info.choices);
        case ValueType::real_list:
            return "a list of numbers" + unit;
        case ValueType::string_list:
            return "a list of strings" + choices;
    }
    return "a value";
}

void report_missing(const YAML::Node& map, const std::string& path, const std::string& expected, const std::string& doc,
                    const Reporter& reporter) {
    reporter.error(map, path, "required key is missing (" + expected + ")" + (doc.empty() ? "" : ": " + doc));
}

Section read_section(const Entry& map, const std::string& path, const SectionKeys& keys, const Reporter& reporter) {
    Section section;
    if (!map.value.IsMap()) {
        reporter.error(map.site(), path,
                       "expected a mapping with the keys of " + keys.what + ", got " + describe(map.value));
        section.valid = false;
        return section;
    }
    for (auto it = map.value.begin(); it != map.value.end(); ++it) {
        const Entry entry{it->first, it->second};
        if (!entry.key.IsScalar()) {
            reporter.error(entry.key, path, "expected a key name, got " + describe(entry.key));
            section.valid = false;
            continue;
        }
        const std::string name = entry.key.Scalar();
        if (section.given.contains(name)) continue;  // a duplicate, reported when the file was read
        const auto info = std::find_if(keys.params.begin(), keys.params.end(), [&](auto& p) { return p.key == name; });
        const bool other = std::find(keys.other_keys.begin(), keys.other_keys.end(), name) != keys.other_keys.end();
        if (info == keys.params.end() && !other) {
            if (keys.report_unknown) report_unknown(entry.key, path, keys, reporter);
            section.valid = false;
            continue;
        }
        section.given.emplace(name, entry);
        if (info == keys.params.end()) continue;
        if (auto value = read_value(*info, entry, join_path(path, name), reporter))
            section.values.emplace(name, *value);
        else
            section.valid = false;
    }
    for (const auto& p : keys.params) {
        if (!p.required || section.given.contains(p.key)) continue;
        report_missing(map.value, join_path(path, p.key), expectation(p), p.doc, reporter);
        section.valid = false;
    }
    return section;
}

void emit_value(YAML::Emitter& out, const ParamValue& value) {
    struct Visitor {
        YAML::Emitter& out;
        void operator()(bool b) const { out << (b ? "true" : "false"); }
        void operator()(std::int64_t i) const { out << std::to_string(i); }
        void operator()(double x) const { out << real_text(x); }
        void operator()(const std::string& s) const { emit_string(out, s); }
        void operator()(const std::vector<double>& v) const {
            out << YAML::Flow << YAML::BeginSeq;
            // Lists hold block indices as often as lengths: a whole number is written as one
            // (`blocks: [5]`), which reads back as the same real.
            for (double x : v) out << (is_whole(x) ? std::to_string(static_cast<std::int64_t>(x)) : real_text(x));
            out << YAML::EndSeq;
        }
        void operator()(const std::vector<std::string>& v) const {
            out << YAML::Flow << YAML::BeginSeq;
            for (const auto& s : v) emit_string(out, s);
            out << YAML::EndSeq;
        }
    };
    std::visit(Visitor{out}, value);
}

std::string yaml_text(const ParamValue& value) {
    YAML::Emitter out;
    emit_value(out, value);
    return out.c_str();
}

}  // namespace frictionlab::detail
