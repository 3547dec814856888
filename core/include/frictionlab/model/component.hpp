#pragma once
// The root of every plugin type, and the kinds users name in a scene.
#include <string_view>

namespace frictionlab {

enum class Kind { bulk_model, friction_law, loader, observer, integrator };

/// Scene and CLI spelling of a kind: "bulk_model", "friction_law", "loader", "observer", "integrator".
std::string_view to_string(Kind);

/// Every object a plugin creates derives from this (through one of the kinds), so the registry can
/// own and hand out objects of any kind. The out-of-line destructor anchors the vtable in the core.
class Component {
public:
    virtual ~Component();
    Component() = default;
    Component(const Component&) = delete;
    Component& operator=(const Component&) = delete;
};

}  // namespace frictionlab
