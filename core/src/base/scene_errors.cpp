#include "frictionlab/base/scene_errors.hpp"

namespace frictionlab {

namespace {
std::string formatted(const Diagnostics& d) {
    std::string text = d.format();
    if (!text.empty() && text.back() == '\n') text.pop_back();
    return text;
}

Diagnostics one(Diagnostic d) {
    Diagnostics all;
    all.error(std::move(d.where), std::move(d.key_path), std::move(d.message));
    return all;
}
}  // namespace

SceneErrors::SceneErrors(Diagnostics diagnostics) : InputError(formatted(diagnostics)), diagnostics_(diagnostics) {}

SceneErrors::SceneErrors(Diagnostic diagnostic) : SceneErrors(one(std::move(diagnostic))) {}

// The key function: it anchors the vtable in the core library (errors.hpp says why).
SceneErrors::~SceneErrors() = default;

}  // namespace frictionlab
