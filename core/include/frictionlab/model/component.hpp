#pragma once
// The root of every plugin type, and the kinds users name in a scene.
#include <string_view>

namespace cereal {
class PortableBinaryOutputArchive;
class PortableBinaryInputArchive;
}  // namespace cereal

namespace frictionlab {

using StateOut = cereal::PortableBinaryOutputArchive;  // frictionlab/base/state_archive.hpp
using StateIn = cereal::PortableBinaryInputArchive;

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

    /// Checkpoints (share/docs/checkpoints.md): whether save_state() writes everything this object
    /// keeps beyond its parameters and the state vector (junction states, anchors, clocks, draw
    /// counters, a rupture in progress), so that a run resumed from it goes on bit-identically. A run
    /// asked for checkpoints names every component that says no. Safe by default: no.
    virtual bool checkpointable() const { return false; }
    /// Writes that state at a checkpoint (after a whole step; nothing may change).
    virtual void save_state(StateOut&) const {}
    /// Reads back what save_state() wrote, after the component was built from the same scene and its
    /// stage begun: it replaces whatever the construction and begin_stage() set.
    virtual void restore_state(StateIn&) {}
};

}  // namespace frictionlab
