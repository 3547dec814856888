#pragma once
// What a run's checkpoint holds (share/docs/checkpoints.md), and how it is checked on resume. Each
// component's state is archived on its own, so that a state that does not read back is reported
// with the component's name, and observers can be restored after they have reopened their files.
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "frictionlab/model/component.hpp"
#include "frictionlab/output/checkpoint_file.hpp"
#include "frictionlab/output/run_info.hpp"

namespace frictionlab {

struct RunCheckpoint {
    // Identity: a resume refuses a checkpoint of another framework, ABI, scene or plugin build.
    std::string framework_version;
    std::uint32_t framework_abi = 0;
    std::string scene_hash;
    std::vector<std::pair<std::string, std::string>> plugins;  // name, file fingerprint
    // Where the run was:
    std::uint64_t stage = 0;
    double stage_start = 0;
    std::string system, quantities, integrator;  // archived states
    struct ObserverState {
        double next_time = 0;
        long long last_step = -1;
        double last_time = -INFINITY;
        double finer_next = INFINITY;
        std::string state;
        template <class Archive>
        void serialize(Archive& ar) {
            ar(next_time, last_step, last_time, finer_next, state);
        }
    };
    std::vector<ObserverState> observers;
    OutputLengths outputs;

    template <class Archive>
    void serialize(Archive& ar) {
        ar(framework_version, framework_abi, scene_hash, plugins, stage, stage_start, system, quantities, integrator,
           observers, outputs);
    }

    /// The identity fields of a run with `info`.
    static RunCheckpoint identity_of(const RunInfo& info);
    std::string payload() const;
    /// Throws RunError when the payload does not read back.
    static RunCheckpoint from_payload(const std::string& payload);
    /// Throws RunError with the reason when this checkpoint is not of the run `now` describes.
    void check_same_run(const RunCheckpoint& now) const;
};

/// What `save` writes to an archive, as bytes; and `restore` reading them back, a state that does
/// not read back whole being a RunError naming `who`.
std::string archived(const std::function<void(StateOut&)>& save);
void restore_archived(const std::string& state, const std::string& who, const std::function<void(StateIn&)>& restore);

/// The same for a component's own state (Component::save_state, restore_state).
std::string archived_state(const Component& component);
void restore_archived_state(Component& component, const std::string& state, const std::string& who);

}  // namespace frictionlab
