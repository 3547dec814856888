#include "type_selector.hpp"

#include <optional>

#include "frictionlab/base/errors.hpp"

namespace frictionlab::cli {

namespace {

constexpr Kind kinds[] = {Kind::bulk_model, Kind::friction_law, Kind::loader, Kind::integrator, Kind::observer};

std::optional<Kind> kind_named(const std::string& name) {
    for (auto kind : kinds)
        if (to_string(kind) == name) return kind;
    return std::nullopt;
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
    if (!kind)
        throw InputError("unknown kind '" + kind_name +
                         "' (kinds: bulk_model, friction_law, loader, integrator, observer)");
    if (slash == std::string::npos) return registry.types(*kind);
    const std::string type = selector.substr(slash + 1);
    if (const auto* t = registry.find(*kind, type)) return {t};
    std::string known;
    for (const auto* t : registry.types(*kind)) known += (known.empty() ? "" : ", ") + t->type;
    throw InputError("no " + kind_name + " type '" + type + "' (available: " + known + ")");
}

}  // namespace frictionlab::cli
