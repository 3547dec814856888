#include "type_selector.hpp"

#include <optional>

#include "frictionlab/base/diagnostics.hpp"
#include "frictionlab/base/errors.hpp"

namespace frictionlab::cli {

namespace {

constexpr Kind kinds[] = {Kind::bulk_model, Kind::friction_law, Kind::loader, Kind::integrator, Kind::observer};

std::optional<Kind> kind_named(const std::string& name) {
    for (auto kind : kinds)
        if (to_string(kind) == name) return kind;
    return std::nullopt;
}

std::vector<std::string> kind_names() {
    std::vector<std::string> names;
    for (auto kind : kinds) names.emplace_back(to_string(kind));
    return names;
}

std::vector<std::string> type_names(const std::vector<const TypeInfo*>& types) {
    std::vector<std::string> names;
    for (const auto* t : types) names.push_back(t->type);
    return names;
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

/// "; did you mean 'x'?" for a misspelt name, "" for one close to none of `known`.
std::string near_miss(const std::string& name, const std::vector<std::string>& known) {
    const std::string guess = did_you_mean(name, known);
    return guess.empty() ? "" : "; did you mean '" + guess + "'?";
}

}  // namespace

std::vector<const TypeInfo*> all_types(const Registry& registry) {
    std::vector<const TypeInfo*> out;
    for (auto kind : kinds)
        for (const auto* t : registry.types(kind)) out.push_back(t);
    return out;
}

std::vector<const TypeInfo*> select_types(const Registry& registry, const std::string& selector) {
    if (selector.empty()) return all_types(registry);
    const auto slash = selector.find('/');
    const std::string kind_name = selector.substr(0, slash);
    const auto kind = kind_named(kind_name);
    if (slash == std::string::npos && !kind) {
        std::vector<const TypeInfo*> named;
        for (const auto* t : all_types(registry))
            if (t->type == selector) named.push_back(t);
        if (!named.empty()) return named;
        std::vector<std::string> known = kind_names();
        for (const auto& name : type_names(all_types(registry))) known.push_back(name);
        throw InputError("no kind or type '" + selector + "'" + near_miss(selector, known) +
                         " (kinds: " + joined(kind_names()) + "; `frictionlab list` names every type)");
    }
    if (!kind)
        throw InputError("unknown kind '" + kind_name + "'" + near_miss(kind_name, kind_names()) +
                         " (kinds: " + joined(kind_names()) + ")");
    if (slash == std::string::npos) return registry.types(*kind);
    const std::string type = selector.substr(slash + 1);
    if (const auto* t = registry.find(*kind, type)) return {t};
    const auto known = type_names(registry.types(*kind));
    throw InputError("no " + kind_name + " type '" + type + "'" + near_miss(type, known) +
                     " (available: " + joined(known) + ")");
}

std::string one_line(const TypeInfo& type) {
    // What it is ends at the first full stop or colon outside parentheses ("(Li et al. 2020)",
    // "Thøgersen et al. (2019)" and "doi:10..." do not end it); a colon introduces how it works, which
    // `doc` gives.
    const std::string& s = type.summary;
    int depth = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        depth += s[i] == '(' ? 1 : s[i] == ')' ? -1 : 0;
        const bool ends_a_word = i + 1 == s.size() || s[i + 1] == ' ';
        const bool abbreviation = i >= 5 && s.compare(i - 5, 6, "et al.") == 0;
        if (depth <= 0 && ends_a_word && s[i] == '.' && !abbreviation) return s.substr(0, i + 1);
        if (depth <= 0 && ends_a_word && s[i] == ':') return s.substr(0, i);
    }
    return s;
}

}  // namespace frictionlab::cli
