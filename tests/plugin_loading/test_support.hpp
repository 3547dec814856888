#pragma once
// Shared by the plugin-loading tests: where the test plugins are, the message a refusal carries,
// and a comparable picture of a registry to show that a refusal changed nothing.
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/plugins/registry.hpp"

namespace frictionlab::test {

inline std::filesystem::path test_plugin(const std::string& file) {
    return std::filesystem::path(TEST_PLUGIN_DIR) / file;
}

/// The InputError message `f` throws; a test failure (and "") if it throws none.
template <class F>
std::string refusal(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected an InputError";
    return {};
}

/// Every registered type (kind, name, library) and every loaded plugin (name, version, file).
inline auto snapshot(const Registry& registry) {
    std::vector<std::tuple<Kind, std::string, std::string>> types;
    for (Kind k : {Kind::bulk_model, Kind::friction_law, Kind::loader, Kind::observer, Kind::integrator})
        for (const TypeInfo* t : registry.types(k)) types.emplace_back(k, t->type, t->library);
    std::vector<std::tuple<std::string, std::string, std::string>> plugins;
    for (const auto& p : registry.plugins()) plugins.emplace_back(p.name, p.version, p.file.string());
    return std::make_pair(types, plugins);
}

}  // namespace frictionlab::test
